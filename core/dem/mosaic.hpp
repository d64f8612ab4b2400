#pragma once
// Several DEMs on one grid: same CRS, same cell size, offsets a whole number of cells apart.
// Cells shared by neighbouring tiles (SRTM tiles repeat their edge row/column) are counted
// once: N00E010.hgt + N00E011.hgt.zip is 2401x1201. Cells no input covers are voids.
#include <vector>

#include "core/dem/dem.hpp"

namespace ts::dem {

// Throws ts::InputError naming the offending file on a CRS, resolution, rotation or
// alignment mismatch. One input is returned as is.
Dem mosaic(std::vector<Dem> parts);

}  // namespace ts::dem
