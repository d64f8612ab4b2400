#pragma once
// Where placed sphere blockers (core/blockers/placed_spheres.hpp) can change a height grid's
// texels: bounding rectangles from the root of each mesh's sphere hierarchy, and the receiver
// positions in the mesh's anchor frame. Only the texels inside are ever visited, so everything
// outside stays bit-identical to a render without the mesh (docs/blockers.md, "Footprints").
#include <glm/vec3.hpp>

#include "core/blockers/placed_spheres.hpp"
#include "core/terrain/height_grid.hpp"

namespace ts::visibility {

// Texels [col0, col1) x [row0, row1) of a grid; empty when col0 >= col1 or row0 >= row1.
struct TexelRect {
    int col0 = 0, row0 = 0, col1 = 0, row1 = 0;
    bool empty() const { return col0 >= col1 || row0 >= row1; }
    long long texels() const { return empty() ? 0 : (long long)(col1 - col0) * (row1 - row0); }
    bool contains(int c, int r) const { return c >= col0 && c < col1 && r >= row0 && r < row1; }
};

// The receiver at texel (c, r) in the mesh's anchor frame (placed_spheres.hpp); curvature is
// 1 / (2 R_eff) or 0 (earth_curvature.hpp).
inline glm::dvec3 receiver_in_anchor_frame(const terrain::HeightGrid& g, int c, int r,
                                           const blockers::PlacedSpheres& mesh, double curvature) {
    const double e = (c - mesh.anchor.x) * g.dx_m[std::size_t(r)];
    const double n = (mesh.anchor.y - r) * g.dy_m[std::size_t(r)];
    return {e, n, double(g.at(c, r)) - (e * e + n * n) * curvature};
}

// Sky: texels within horizontal distance R / min_sine of the root sphere (R its radius), the
// farthest at which it (and so any sphere inside it) still subtends the threshold.
TexelRect sky_footprint(const terrain::HeightGrid& g, const blockers::PlacedSpheres& mesh, double min_sine);

// Sun: the root sphere's shadow cylinder along `sun` (unit, ENU), widened by the penumbra cone
// of the disc, between the heights z_low and z_high the receivers may have in the anchor frame
// (the grid's range, z_low lowered by the largest curvature drop), projected onto the ground
// plane. Empty when the sun is below the horizon.
TexelRect sun_footprint(const terrain::HeightGrid& g, const blockers::PlacedSpheres& mesh, const glm::dvec3& sun,
                        double sun_radius, double z_low, double z_high);

// Lowest and highest valid height of the grid (NaN voids skipped; {0, 0} when all void).
struct HeightRange {
    double low = 0, high = 0;
};
HeightRange height_range(const terrain::HeightGrid& g);

// The largest curvature drop of any texel in the mesh's anchor frame (curvature: 1 / (2 R_eff)
// or 0): the grid's corner farthest from the anchor, its distances from the rows' largest
// spacing, so it bounds a geographic grid's too. sun_footprint's z_low is lowered by it.
double largest_curvature_drop(const terrain::HeightGrid& g, const blockers::PlacedSpheres& mesh, double curvature);

}  // namespace ts::visibility
