#pragma once
// What every DEM reader checks before it allocates a decoded raster: that the cells fit in
// the memory the machine has now. A refusal is one ts::InputError naming the file and how
// much it would take, instead of an allocation that swaps for minutes or is OOM-killed.
#include <cstdint>
#include <string>

namespace ts::dem {

// Bytes one cell costs in a Dem: its float height and its void flag.
inline constexpr std::uint64_t kBytesPerCell = sizeof(float) + 1;

// The most cells one Dem holds (read whole or mosaicked). Readers that stream windows
// (DemSource) need no such cap: only each side must fit an int.
inline constexpr std::uint64_t kMaxDemCells = std::uint64_t(1) << 31;

// Throws ts::InputError "source: ..." when `what` (e.g. "decoding") of width x height cells,
// plus `buffer_bytes` of decoding buffers, needs more than ts::available_memory().
void require_memory_for(const std::string& source, const std::string& what, std::uint64_t width, std::uint64_t height,
                        std::uint64_t buffer_bytes = 0);

}  // namespace ts::dem
