#pragma once
// Several DEMs on one grid: same CRS, same cell size, offsets a whole number of cells apart.
// Cells shared by neighbouring tiles (SRTM tiles repeat their edge row/column) are counted
// once: N00E010.hgt + N00E011.hgt.zip is 2401x1201. Cells no input covers are voids.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/dem/dem.hpp"
#include "core/dem/dem_layout.hpp"

namespace ts::dem {

// Throws ts::InputError naming the offending file on a CRS, resolution, rotation or
// alignment mismatch. One input is returned as is.
Dem mosaic(std::vector<Dem> parts);

// Where each part lies on the mosaic's grid, from the parts' grids alone (what mosaic() and
// DemSource, which reads the cells later, both need).
struct MosaicPlan {
    DemLayout layout;
    // The mosaic cell (column, row) of each part's cell (0, 0), in the order of the parts.
    std::vector<std::pair<int, int>> offsets;
};
// The checks and errors of mosaic(); one part is its own plan. Each side of the mosaic must
// fit an int; how many cells the whole may have is the caller's limit.
MosaicPlan plan_mosaic(const std::vector<DemLayout>& parts);

// How a part's `n` cells join cells of the mosaic, parts taken in order: a height fills a cell
// that is still void, a void never hides a height, so the first valid height wins.
void merge_into(const float* z, const std::uint8_t* voids, float* out_z, std::uint8_t* out_voids, std::size_t n);

}  // namespace ts::dem
