#pragma once
// Unit surface normals of a height grid in the local ENU frame (x east, y north, z up), from
// central differences with the true metric spacing of each row (HeightGrid::dx_m/dy_m), so a
// geographic DEM's slopes are right at every latitude. One-sided differences on the edges;
// a hole (NaN) neighbour is skipped the same way; a texel with no valid neighbour on an axis
// gets slope 0 on it; a hole texel itself gets (0, 0, 1).
//
// Geometry of the height grid, so it lives in core/terrain, below the materials and the
// renderer that both use it. Its names stay in ts::render for now: the renderer's files name
// them unqualified (docs/architecture.md, "Namespaces").
#include <vector>

#include "core/terrain/height_grid.hpp"

namespace ts::render {

// SoA: nx, ny, nz, each width*height, row-major (row 0 = north).
struct NormalField {
    std::vector<float> x, y, z;
};

NormalField terrain_normals(const terrain::HeightGrid& grid, int threads = 0);

// Slope angle in degrees (0 = flat) from a unit normal's up component.
double slope_deg(float nz);

}  // namespace ts::render
