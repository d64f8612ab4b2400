#pragma once
// Cropping a DEM to a WGS84 lon/lat box or a window of texels.
#include "core/dem/dem.hpp"

namespace ts::dem {

struct LonLatBox {
    double west = 0, south = 0, east = 0, north = 0;  // degrees
};

// Keeps every cell that overlaps the box (the box's outline is projected into the DEM's CRS,
// so a lon/lat box on a projected grid keeps its whole curved footprint). Throws
// ts::InputError when the box is malformed or misses the DEM.
Dem crop(const Dem& dem, const LonLatBox& box);

// The texels [col0, col0 + width) x [row0, row0 + height), clipped to the DEM (at least one
// texel), with their void mask and georef.
Dem texel_window(const Dem& dem, int col0, int row0, int width, int height);

}  // namespace ts::dem
