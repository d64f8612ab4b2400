#pragma once
// The HeightGrid view of a Dem, with per-row spacing from the Dem's georeferencing.
#include "core/dem/dem.hpp"
#include "core/terrain/height_grid.hpp"

namespace ts::terrain {

// Spacing of row r = Georef::cell_size_m at the centre of the row's middle texel: true metres
// on the ellipsoid (for projected grids this includes the projection's scale factor, so a
// Web Mercator DEM gets ground distances, not map units). `dem` must outlive the view.
// Throws ts::InputError if the Dem has no georeferencing.
HeightGrid metric_view(const dem::Dem& dem);

}  // namespace ts::terrain
