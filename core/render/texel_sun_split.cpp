#include "core/render/texel_sun_split.hpp"

#include <algorithm>
#include <cmath>

#include "core/util/angles.hpp"
#include "core/visibility/sun_visibility.hpp"

namespace ts::render {

void split_texel_sun(const Scene& scene, const SunState& sun, const light::Sky& sky,
                     std::span<const glm::vec3> radiance, TexelSunSplit& out) {
    const MaterialRaster& m = scene.state().materials();
    const NormalField& nf = scene.state().normals();
    const std::vector<float>& sun_vis = scene.renderer().sun_visibility();
    const std::vector<float>& horizon = scene.renderer().sun_horizon();
    const light::SunDisc disc = sky.sun();
    const glm::vec3 s = glm::vec3(sun_direction(sun));
    const glm::vec3 e = disc.irradiance * float(1.0 / kPi);
    const float band = float(visibility::kSunHorizonBandRad);
    const std::size_t n = radiance.size();
    out.rest.resize(n), out.sun_albedo.resize(n), out.horizon_above_sun.resize(n);
    for (std::size_t t = 0; t < n; ++t) {
        const float v = std::isnan(sun_vis[t]) ? 0.0f : sun_vis[t];
        const float w = v * std::max(0.0f, nf.x[t] * s.x + nf.y[t] * s.y + nf.z[t] * s.z);
        glm::vec3 a = glm::vec3(m.albedo_r[t], m.albedo_g[t], m.albedo_b[t]) * e;
        // The frame's sun term, never more than its radiance (a water or glossy texel's rest
        // holds its own sun); where that bound bites, a is lowered so the split still adds up.
        const glm::vec3 part = glm::min(a * w, radiance[t]);
        if (w > 0) a = part / w;
        out.rest[t] = radiance[t] - part;
        out.sun_albedo[t] = a;
        float h = horizon.size() == n ? horizon[t]
                                      : float(visibility::horizon_above_sun_for_fraction(v, disc.angular_radius_rad));
        if (std::isnan(sun_vis[t]) || std::isnan(h)) h = band;
        out.horizon_above_sun[t] = std::clamp(h, -band, band);
    }
}

}  // namespace ts::render
