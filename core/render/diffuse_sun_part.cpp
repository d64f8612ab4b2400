#include "core/render/diffuse_sun_part.hpp"

#include <algorithm>

#include "core/util/angles.hpp"

namespace ts::render {

void diffuse_sun_part(const Scene& scene, const SunState& sun, const light::Sky& sky,
                      std::span<const glm::vec3> radiance, std::vector<glm::vec3>& out) {
    const MaterialRaster& m = scene.state().materials();
    const NormalField& nf = scene.state().normals();
    const std::vector<float>& sun_vis = scene.renderer().sun_visibility();
    const glm::vec3 s = glm::vec3(sun_direction(sun));
    const glm::vec3 e = sky.sun().irradiance * float(1.0 / kPi);
    out.resize(radiance.size());
    for (std::size_t t = 0; t < radiance.size(); ++t) {
        const float v = sun_vis[t] == sun_vis[t] ? sun_vis[t] : 0.0f;
        const float w = v * std::max(0.0f, nf.x[t] * s.x + nf.y[t] * s.y + nf.z[t] * s.z);
        out[t] = glm::min(glm::vec3(m.albedo_r[t], m.albedo_g[t], m.albedo_b[t]) * e * w, radiance[t]);
    }
}

}  // namespace ts::render
