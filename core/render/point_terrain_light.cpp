#include "core/render/point_terrain_light.hpp"

#include <algorithm>
#include <vector>

#include "core/sh/sh_exp.hpp"
#include "core/sh/sh_product.hpp"
#include "core/sh/slice_projector.hpp"

namespace ts::render {

PointTerrainLighting::PointTerrainLighting(const terrain::HeightGrid& grid, const PointTerrainLightOptions& options)
    : options_(options), horizons_(grid, visibility::PointHorizonOptions{options.curvature, 0.25, options.base_plane}) {
    options_.directions = std::max(4, options_.directions);
}

void PointTerrainLighting::horizons(glm::dvec2 texel, double z, float* out) const {
    horizons_.horizons(texel, z, options_.directions, out);
}

double PointTerrainLighting::sun_fraction(glm::dvec2 texel, double z, const glm::dvec3& sun, double sun_radius_rad) const {
    return std::clamp(horizons_.sun_fraction(texel, z, sun, sun_radius_rad), 0.0, 1.0);
}

PointTerrainLight PointTerrainLighting::light_from(const float* sigma, double sun_fraction, const light::SkySh& sky_sh) const {
    float log_v[16], v[16];
    sh::SliceProjector(options_.directions).project_horizons(sigma, options_.terrain_log_eps, log_v);
    sh::sh_exp(options_.exp_method, log_v, v);
    PointTerrainLight out;
    for (int c = 0; c < 3; ++c) {
        float l[16], lv[16];
        for (int i = 0; i < 16; ++i) l[i] = sky_sh[std::size_t(i)][c];
        sh::product(v, l, lv);
        for (int i = 0; i < 16; ++i) out.visible_sky[std::size_t(i)][c] = lv[i];
    }
    out.sun_fraction = float(sun_fraction);
    return out;
}

PointTerrainLight PointTerrainLighting::light(glm::dvec2 texel, double z, const light::SkySh& sky_sh,
                                              const glm::dvec3& sun, double sun_radius_rad) const {
    std::vector<float> sigma(static_cast<std::size_t>(options_.directions));
    horizons(texel, z, sigma.data());
    return light_from(sigma.data(), sun_fraction(texel, z, sun, sun_radius_rad), sky_sh);
}

}  // namespace ts::render
