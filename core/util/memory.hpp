#pragma once
// How much memory the process may still use, so readers can refuse a raster that cannot fit
// before they allocate it (a failed multi-gigabyte allocation is an OOM kill or a long swap
// storm, not a clean std::bad_alloc).
#include <cstdint>
#include <string>

namespace ts {

// Bytes available now: MemAvailable from /proc/meminfo, no more than a cgroup memory limit
// (v2 memory.max, v1 memory.limit_in_bytes) and no more than memory_cap(). UINT64_MAX when the
// system says nothing (not Linux): then only the cap limits.
std::uint64_t available_memory();

// A ceiling below the machine's memory, for code that must stay small whatever the machine
// has (fuzz targets under libFuzzer's RSS limit). 0 removes it. Process-wide, not thread-safe
// against concurrent available_memory() calls: set it once at start-up.
void set_memory_cap(std::uint64_t bytes);
std::uint64_t memory_cap();

// "7.5 GB", "512 MB", "980 bytes": decimal units, as df and free -H print them.
std::string format_bytes(std::uint64_t bytes);

}  // namespace ts
