#include "core/render/pixel_sun_blockers.hpp"

#include <algorithm>
#include <cmath>

#include "core/blockers/receiver_blockers.hpp"
#include "core/blockers/sun_disc_samples.hpp"

namespace ts::render {

PixelSunBlockers::PixelSunBlockers(const terrain::HeightGrid& grid, const blockers::SphereBlockers& blockers,
                                   double curvature)
    : grid_(grid), blockers_(blockers), curvature_(curvature), range_(visibility::height_range(grid)) {
    for (const blockers::PlacedSpheres& m : blockers.meshes)
        max_drop_.push_back(visibility::largest_curvature_drop(grid, m, curvature));
}

void PixelSunBlockers::set_sun(const glm::dvec3& sun) {
    sun_ = sun;
    const double radius = blockers_.options.sun_radius_rad;
    rects_.clear();
    for (std::size_t k = 0; k < blockers_.meshes.size(); ++k)
        rects_.push_back(visibility::sun_footprint(grid_, blockers_.meshes[k], sun, radius, range_.low - max_drop_[k],
                                                   range_.high));
    const bool by_triangles = blockers_.options.sun_caster == blockers::SphereBlockerOptions::SunCaster::triangles;
    disc_ = by_triangles ? blockers::sun_disc_directions(sun, radius, blockers_.options.sun_rays)
                         : std::vector<glm::dvec3>{};
}

double PixelSunBlockers::visible(double x, double y, double z) const {
    double left = 1.0;
    const int row = std::clamp(int(std::lround(y)), 0, grid_.height - 1);
    for (std::size_t k = 0; k < rects_.size() && left > 0; ++k) {
        const visibility::TexelRect& rect = rects_[k];
        // The rectangle holds the footprint's texels; a point between them may lie a texel out.
        if (x < rect.col0 - 1 || x > rect.col1 || y < rect.row0 - 1 || y > rect.row1) continue;
        const blockers::PlacedSpheres& m = blockers_.meshes[k];
        const double e = (x - m.anchor.x) * grid_.dx_m[std::size_t(row)];
        const double n = (m.anchor.y - y) * grid_.dy_m[std::size_t(row)];
        const glm::dvec3 p{e, n, z - (e * e + n * n) * curvature_};
        double mesh_left = blockers::sun_visible_past(m, p, sun_, blockers_.options.sun_radius_rad);
        if (!disc_.empty() && m.model_triangles && mesh_left < 1.0)
            mesh_left = blockers::sun_visible_past_triangles(m, p, disc_);
        left *= mesh_left;
    }
    return left;
}

}  // namespace ts::render
