#pragma once
// Where a DEM lies on the Web Mercator map: its outline carried to lon/lat (through the DEM's
// CRS, so any CRS the readers take works) and the tiles of each zoom that it touches.
#include <vector>

#include "core/dem/dem.hpp"
#include "core/geo/georef.hpp"
#include "core/tiles/web_mercator.hpp"

namespace ts::tiles {

// A lon/lat box in degrees (west, south, east, north), latitudes within Web Mercator's range.
struct LonLatBox {
    double west = 0, south = 0, east = 0, north = 0;
    bool empty() const { return !(east > west && north > south); }
};

// The bounding box of the DEM's outline (64 points per edge, so a projected DEM's curved edges
// are followed), clipped to +-kMaxLatitudeDeg. Empty if the DEM lies beyond Web Mercator.
LonLatBox dem_footprint(const geo::Georef& georef);

// The bounding box of the DEM's terrain: the texels with a height, leaving out those outside it
// (NaN: a reprojection's nodata collar, docs/terrain.md). The corners of each row's and each
// column's first and last terrain texels are carried to lon/lat, so the outline of the terrain
// is followed to a texel. Without outside texels, dem_footprint(dem.georef) exactly.
LonLatBox terrain_footprint(const dem::Dem& dem);

// The XYZ tiles of zooms z0..z1 that the box touches (a tile that only shares an edge with it is
// left out), zoom by zoom, rows then columns.
std::vector<TileId> tiles_covering(const LonLatBox& box, int z0, int z1);

}  // namespace ts::tiles
