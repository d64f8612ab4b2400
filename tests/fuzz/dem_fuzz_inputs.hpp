#pragma once
// How a fuzz input's bytes reach each DEM reader, shared by the libFuzzer targets
// (fuzz_*.cpp) and the GoogleTest that replays the corpus and every crash found
// (tests/dem/fuzz_regressions_test.cpp), so a regression file is replayed exactly as found.
#include <cstddef>
#include <cstdint>
#include <string>

namespace ts::fuzz {

// The memory a reader may count on while fuzzing (ts::set_memory_cap): a 1201x1201 tile
// (7.2 MB) still fits, a larger raster is an InputError. scripts/fuzz.sh reports any single
// allocation over 128 MB: a reader that allocates before it checks is caught at a header
// claiming ~6000x6000 cells, which mutations of tiny seeds reach, not only at gigabytes.
inline constexpr std::uint64_t kMemoryCap = 32u << 20;

enum class Outcome { read, input_error };

// .hgt, in memory (read_hgt_bytes): byte 0 holds flags, then a file name up to the first
// '\n' (which gives the tile's corner), then the tile's bytes. Flag bit 0 pads or cuts the
// bytes to a 1201x1201 tile so that mutations reach the decoding, not only the size check.
Outcome feed_hgt(const std::uint8_t* data, std::size_t size);
// .hgt.zip: the bytes as a zip archive named N00E011.hgt.zip, through read_hgt_zip.
Outcome feed_hgt_zip(const std::uint8_t* data, std::size_t size);
// GeoTIFF: the bytes as a .tif file, through read_geotiff.
Outcome feed_geotiff(const std::uint8_t* data, std::size_t size);

// The feed for a corpus folder name: "hgt", "hgt_zip" or "geotiff"; nullptr otherwise.
using Feed = Outcome (*)(const std::uint8_t*, std::size_t);
Feed feed_for(const std::string& reader);

}  // namespace ts::fuzz
