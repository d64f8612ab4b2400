#pragma once
// Rays over a height grid's smooth surface (core/terrain/smooth_surface.hpp), in texel-centre
// coordinates with heights in metres: the first crossing of a camera's ray, and the highest
// elevation of the terrain seen along a ray towards the sun. A max pyramid over the patches
// between texel centres (level 0 = each patch's bound, terrain::smooth_patch_bound, then 2x2
// maxima, terrain::downsample_2x2) lets a ray skip every cell it passes above.
#include <vector>

#include <glm/vec3.hpp>

#include "core/terrain/height_grid.hpp"

namespace ts::render {

// A ray parameterised by its horizontal distance s in metres.
struct SurfaceRay {
    double x0 = 0, y0 = 0;          // texel-centre coordinates at s = 0
    double ux = 0, uy = 0;          // texel units per horizontal metre
    // height(s) = z0 + kz s + curv s^2 (curv: the terrain's drop with distance, as a lift of the ray)
    double z0 = 0, kz = 0, curv = 0;
    double height_at(double s) const { return z0 + s * (kz + s * curv); }
    double min_height(double s0, double s1) const;
};

class SurfaceMarch {
public:
    SurfaceMarch(const terrain::HeightGrid& grid, int threads);

    // The first s in [s_begin, s_end] where the ray is at or below the surface (within a
    // 1/4096 of a patch's crossing), or < 0. `nudge` (metres) steps a ray past a cell's edge.
    double first_hit(const SurfaceRay& ray, double s_begin, double s_end, double nudge) const;

    // The highest tangent of elevation (z(s) - z0 - curv s^2) / s over s in [s_begin, s_end],
    // sampled at least every quarter patch, counting only what rises above `floor_tan` (below
    // it returns floor_tan) and stopping once above `ceiling_tan`: a sun's disc only cares
    // about its own band. `ray.kz` is ignored.
    double horizon_tangent(const SurfaceRay& ray, double s_begin, double s_end, double floor_tan, double ceiling_tan,
                           double nudge) const;

    // The share of the sun's disc (unit direction `sun` in ENU, angular radius in radians) the
    // terrain leaves visible from the surface at texel-centre coordinates (x, y), with the
    // Earth's drop curv s^2 (visibility::curvature_factor). Rays stop at the grid's edge.
    double sun_visible_fraction(double x, double y, const glm::dvec3& sun, double sun_radius_rad, double curv) const;

private:
    // The cell of `level` under the ray at s, and the s where the ray leaves it.
    struct Cell {
        float bound;
        double exit;
    };
    Cell cell_at(const SurfaceRay& ray, int level, double s, double s_end) const;
    // Walks the ray from s_begin to s_end down the pyramid, skipping every cell it passes
    // above, and calls patch(s, exit) for each level-0 patch it may touch (between s and exit);
    // patch returns true to stop. The ray is read at every step: patch may raise it.
    template <class Patch>
    void walk(const SurfaceRay& ray, double s_begin, double s_end, double nudge, Patch&& patch) const;

    const terrain::HeightGrid& grid_;
    std::vector<std::vector<float>> max_;
    std::vector<int> w_, h_;
};

}  // namespace ts::render
