#pragma once
// A job's peak memory, estimated from the DEM's size before the heavy work, and refused with one
// line (and what reduces it) when the machine cannot hold it: a job that does not fit would be
// killed by the kernel or swap for minutes instead of failing cleanly.
//
// Per texel, measured as peak resident memory over the 1201x1201 SRTM3 tile N00E010 (the
// figures in docs/user-guide.md, "Memory"): the visibility pass keeps ~4 bytes per azimuth plus
// ~90 bytes (heights, metric grid, sweep scratch, svf), +110 with the SH products; a render or
// relight keeps ~4 per azimuth plus ~310 (log-SH, transfer vectors, materials, frame buffers,
// and ~85 for the bounce's sun gather, core/render/bounce_sun_gather.hpp), and with meshes 64 more: the terrain's own log-SH, kept for the sky bound and the moves (the
// bound's entries, ~52 bytes per texel a mesh changes, follow the footprints and are left out).
// A margin of 25% covers allocator overhead and the writers' frames.
//
// TERRASHADE_MEMORY_LIMIT (e.g. 4GB, 512MB, or bytes) caps what terrashade plans to use, for
// shared machines and batch jobs: the check then uses the smaller of it and what is available.
#include <cstdint>
#include <string>

namespace ts::app {

std::uint64_t visibility_peak_bytes(std::uint64_t texels, int directions, bool sh_products);
std::uint64_t render_peak_bytes(std::uint64_t texels, int directions, bool meshes = false);

// Throws ts::InputError "<what> needs about X, Y available: <reduce>" when `bytes` exceed the
// available memory (ts::available_memory(), capped by TERRASHADE_MEMORY_LIMIT).
void check_job_memory(const std::string& what, std::uint64_t bytes, const std::string& reduce);

// Reads TERRASHADE_MEMORY_LIMIT into ts::set_memory_cap (at start-up, before any thread);
// throws ts::InputError for a value that is not a size.
void apply_memory_limit_from_environment();

}  // namespace ts::app
