#pragma once
// One zlib stream (RFC 1950) from a whole buffer, by one of two deflate implementations:
//  * ISA-L's igzip (levels 0-3): the fastest deflate there is on x86-64; at level 1 it took
//    a third of libdeflate level 1's time on rendered 500x500 maps for files ~7% larger
//    (docs/dependencies.md, "PNG output"), and encoding is what limits a relit sequence;
//  * libdeflate (levels 0-12): smaller files for more time, for when size matters more.
// Both compress the buffer at once (no streaming state) and are deterministic for a given
// input, level and machine.
#include <cstddef>
#include <cstdint>

namespace ts::raster {

enum class Deflater : std::uint8_t {
    isal,        // ISA-L igzip, levels 0..3
    libdeflate,  // libdeflate, levels 0..12
};

int max_level(Deflater deflater);

// An output capacity that always suffices for `input_size` bytes.
std::size_t zlib_bound(std::size_t input_size);

// Compresses `in` into `out` (capacity `out_capacity` >= zlib_bound) and returns the stream's
// size; 0 if it failed. Thread-safe: each thread keeps its own working memory.
std::size_t zlib_compress(Deflater deflater, int level, const std::uint8_t* in, std::size_t in_size,
                          std::uint8_t* out, std::size_t out_capacity);

}  // namespace ts::raster
