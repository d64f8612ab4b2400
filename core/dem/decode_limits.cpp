#include "core/dem/decode_limits.hpp"

#include <limits>

#include "core/util/error.hpp"
#include "core/util/memory.hpp"

namespace ts::dem {

void require_memory_for(const std::string& source, const std::string& what, std::uint64_t width, std::uint64_t height,
                        std::uint64_t buffer_bytes) {
    // Readers cap width x height at 2^31 cells, so this cannot overflow.
    const std::uint64_t needed = width * height * kBytesPerCell + buffer_bytes;
    const std::uint64_t available = available_memory();
    if (needed <= available) return;
    // --crop (app/dem_input.cpp) crops after the whole raster is read, so it cannot help here.
    throw input_error(source, what + " " + std::to_string(width) + "x" + std::to_string(height) + " cells needs " +
                                  format_bytes(needed) + " of memory but only " + format_bytes(available) +
                                  " is available; cut a smaller window out of it first (a crop reads the whole "
                                  "raster before cropping)");
}

}  // namespace ts::dem
