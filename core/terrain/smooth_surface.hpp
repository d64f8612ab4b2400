#pragma once
// A smooth surface through a height grid's texel centres, for views close enough that one
// texel spans many pixels: Catmull-Rom bicubic, so the surface passes through every height,
// is C1 (no creases along texel lines) and its slope at a texel centre is the central
// difference terrain_normals.hpp uses: per-pixel normals agree with the per-texel ones there.
//
// Edges and voids: a missing neighbour outside the patch's own 2x2 corners is extrapolated
// linearly from the two heights inside (its slope is then the one-sided difference, as in
// terrain_normals); a patch with a void corner falls back to the void-aware bilinear blend
// (valid_bilinear.hpp) and its slope.
#include "core/terrain/height_grid.hpp"

namespace ts::terrain {

struct SurfaceSample {
    float z = 0;                         // NaN: no surface (every corner with weight a void)
    float dz_dcol = 0, dz_drow = 0;      // metres per texel along columns (east) and rows (south)
};

// At texel-centre coordinates (x = column, y = row), clamped onto the grid.
SurfaceSample smooth_surface(const HeightGrid& g, double x, double y);

// smooth_surface's height with a smoother slope, for shading: along each axis the derivative of
// the uniform cubic B-spline through the same 16 heights, across it Catmull-Rom's weights. At a
// texel centre it is the central difference, as smooth_surface's; between centres its rate of
// change has no kink at the texel lines, where Catmull-Rom's does (seen from above, every
// texel of a noisy DEM read as a bump).
SurfaceSample smooth_slope(const HeightGrid& g, double x, double y);

// An upper bound of the surface over the patch between texel centres (col, row) and
// (col + 1, row + 1): a Catmull-Rom patch overshoots the highest of its 16 heights by at most
// 0.28125 of their range. -infinity where the patch has no surface.
float smooth_patch_bound(const HeightGrid& g, int col, int row);

}  // namespace ts::terrain
