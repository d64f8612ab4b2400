#include "core/visibility/blocker_sun_shadow.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "core/blockers/receiver_blockers.hpp"
#include "core/blockers/sun_disc_samples.hpp"
#include "core/geo/azimuth.hpp"
#include "core/util/angles.hpp"
#include "core/util/parallel_for.hpp"

namespace ts::visibility {

BlockerSunShadow::BlockerSunShadow(const terrain::HeightGrid& grid, const blockers::SphereBlockers& blockers,
                                   double curvature, int threads)
    : grid_(grid), blockers_(blockers), curvature_(curvature), threads_(threads), range_(height_range(grid)) {
    for (const blockers::PlacedSpheres& m : blockers.meshes)
        max_drop_.push_back(largest_curvature_drop(grid, m, curvature));
}

TexelRect BlockerSunShadow::footprint(std::size_t k, double azimuth_deg, double elevation_deg) const {
    const glm::dvec3 sun = geo::enu_direction(geo::azimuth_cw_from_north_to_phi(azimuth_deg), radians(elevation_deg));
    return sun_footprint(grid_, blockers_.meshes[k], sun, blockers_.options.sun_radius_rad,
                         range_.low - max_drop_[k], range_.high);
}

SunShadowStats BlockerSunShadow::apply(double azimuth_deg, double elevation_deg, std::vector<float>& vis) const {
    SunShadowStats stats;
    const glm::dvec3 sun = geo::enu_direction(geo::azimuth_cw_from_north_to_phi(azimuth_deg), radians(elevation_deg));
    const double sun_radius = blockers_.options.sun_radius_rad;
    const bool by_triangles = blockers_.options.sun_caster == blockers::SphereBlockerOptions::SunCaster::triangles;
    const std::vector<glm::dvec3> disc =
        by_triangles ? blockers::sun_disc_directions(sun, sun_radius, blockers_.options.sun_rays) : std::vector<glm::dvec3>{};
    for (std::size_t k = 0; k < blockers_.meshes.size(); ++k) {
        const TexelRect rect = footprint(k, azimuth_deg, elevation_deg);
        if (rect.empty()) continue;
        const blockers::PlacedSpheres& m = blockers_.meshes[k];
        const bool triangles = by_triangles && m.model_triangles;
        std::atomic<long long> shadowed{0};
        parallel_rows(rect.row1 - rect.row0, threads_, (long long)(rect.col1 - rect.col0) * 40, [&](int b, int e) {
            long long s = 0;
            for (int r = rect.row0 + b; r < rect.row0 + e; ++r)
                for (int c = rect.col0; c < rect.col1; ++c) {
                    float& v = vis[grid_.index(c, r)];
                    if (!(v > 0.0f)) continue;  // NaN voids, or the terrain already hides the sun
                    const glm::dvec3 p = receiver_in_anchor_frame(grid_, c, r, m, curvature_);
                    // The spheres bound the mesh: where they leave the whole disc, so do its triangles.
                    double left = blockers::sun_visible_past(m, p, sun, sun_radius);
                    if (triangles && left < 1.0) left = blockers::sun_visible_past_triangles(m, p, disc);
                    if (left < 1.0) v = float(double(v) * left), ++s;
                }
            shadowed += s;
        });
        stats.texels_visited += rect.texels();
        stats.texels_shadowed += shadowed;
    }
    return stats;
}

}  // namespace ts::visibility
