#pragma once
// A global grid in degrees has no east or west edge: 180 E is 180 W. Web Mercator tiles meet
// there, and a tile beside it shades its terrain (horizons, normals, the Horn window) from the
// DEM's texels; a grid that ends at 180 gives them a border instead, and a seam runs down the
// map. Such a grid is widened by columns copied from its other side.
#include "core/dem/dem.hpp"

namespace ts::dem {

// Whether `dem` is geographic and spans the whole circle of longitude (within half a cell).
bool spans_all_longitudes(const Dem& dem);

// `dem` widened by `columns` texels on each side, each a copy of the column 360 degrees away
// (heights and void mask; the georef's origin moves west by as much). Unchanged when it does
// not span all longitudes. Columns beyond 180 are what the tiles' pixels and sweeps near 180
// read; Web Mercator's tiles still end at +-180.
Dem wrap_longitudes(const Dem& dem, int columns);

}  // namespace ts::dem
