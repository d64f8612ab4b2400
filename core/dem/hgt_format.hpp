#pragma once
// SRTM .hgt tiles: a square of big-endian int16 heights (EGM96 geoid, metres), row 0 north,
// void = -32768. The file name (N00E010.hgt) names the south-west cell *centre*: cell centres
// sit on whole degrees, so the raster's outer edges lie half a cell outside them. The pieces
// both the whole-file reader (read_hgt) and the window reader (DemSource) use.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/dem/dem_layout.hpp"

namespace ts::dem {

// Side of a tile of `bytes` bytes: 1201 (SRTM3) or 3601 (SRTM1); 0 if neither.
int hgt_side(std::uint64_t bytes);

// Throws ts::InputError "source: ..." unless `bytes` is the size of a tile; from the size
// alone, so callers check it before they read (or inflate) anything.
void require_hgt_size(std::uint64_t bytes, const std::string& source);

// The grid of a tile of side x side cells whose corner ("N00E010") is in `name`; throws
// ts::InputError "source: ..." if the name gives none.
DemLayout hgt_layout(int side, const std::string& name, const std::string& source);

// `n` big-endian int16 samples -> metres; voids NaN with `voids` 1, else 0.
void decode_hgt_heights(const unsigned char* big_endian, std::size_t n, float* z, std::uint8_t* voids);

}  // namespace ts::dem
