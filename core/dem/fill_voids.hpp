#pragma once
// Filling voids (SRTM's -32768 holes, GeoTIFF nodata) so shading has a height where the terrain
// has a gap, and only there.
//
// Voids fall in two kinds (docs/terrain.md, "Outside the terrain"):
//   outside  nodata reachable from the DEM's border through nodata texels by edge-adjacent
//            (4-connected) steps: the collar gdalwarp leaves around a reprojected DEM, or the
//            sea of a coastal tile. It is not terrain: never filled, left NaN.
//   hole     every other connected set of voids: enclosed by measured texels. Filled when each
//            of its texels lies within max_distance texels of a measured one (the Chebyshev
//            distance through the hole, as the peel below counts it), so holes up to about
//            2 * max_distance texels across; a wider hole is left NaN whole, like the outside.
// The flood is 4-connected so that a hole is enclosed as soon as the measured texels around it
// close a ring with diagonal steps too (the dual of a 4-connected background is an 8-connected
// foreground), the ring the filler's 8-neighbour peel reads its heights from. A gap in that
// ring one diagonal step wide does not make the hole part of the outside.
#include <cstddef>

#include "core/dem/dem.hpp"

namespace ts::dem {

// gdal_fillnodata's default -md.
constexpr int kDefaultFillMaxDistance = 100;

struct VoidFillOptions {
    int max_distance = kDefaultFillMaxDistance;  // texels, >= 0 (0 fills nothing)
};

// What one fill found and did. visited counts the texel steps of the flood, the labelling, the
// peel and the relaxation (not the one linear scan that finds the voids), so tests can check
// that the work follows the voids, not the grid.
struct VoidFillStats {
    std::size_t outside_texels = 0;    // border-connected voids, left NaN
    std::size_t filled_texels = 0;     // texels of the holes filled
    std::size_t holes_filled = 0;
    std::size_t unfilled_texels = 0;   // texels of holes wider than max_distance, left NaN
    std::size_t holes_unfilled = 0;
    std::size_t visited = 0;
};

// Fills the holes as above: each hole on its own bounding box, an onion peel (each texel the
// mean of its known 8-neighbours, layer by layer from the rim inward) then over-relaxed Laplace
// sweeps over the hole's texels only (the smooth harmonic surface the rim defines). Measured
// heights never change and void_mask is kept (1 at every void, filled or not), so later stages
// can tell measured from invented; a void left NaN is outside the terrain (HeightGrid::is_hole).
// Throws ts::InputError if the DEM has no valid height at all.
VoidFillStats fill_voids(Dem& dem, const VoidFillOptions& options = {});

// For a renderer that needs a height at every texel (the flythrough's mesh): every texel left
// NaN (outside the terrain) takes the lowest measured height of the DEM, a flat floor beneath
// the terrain; void_mask stays 1 there. Returns how many texels it set.
std::size_t floor_outside(Dem& dem);

// The voids of a DEM counted by kind without filling anything (`terrashade info`): outside
// (border-connected) and the texels of enclosed holes.
struct VoidKinds {
    std::size_t outside_texels = 0;
    std::size_t hole_texels = 0;
    std::size_t holes = 0;
};
VoidKinds classify_voids(const Dem& dem);

}  // namespace ts::dem
