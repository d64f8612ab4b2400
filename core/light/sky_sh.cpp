#include "core/light/sky_sh.hpp"

#include <algorithm>

#include "core/light/hdr_sky.hpp"
#include "core/sh/sh_basis.hpp"

namespace ts::light {

HemisphereRule default_sky_rule(const Sky& sky) {
    HemisphereRule rule{32, 128};
    if (const auto* hdr = dynamic_cast<const HdrSky*>(&sky)) {
        rule.n_phi = std::max(rule.n_phi, hdr->width());
        rule.n_z = std::max(rule.n_z, (hdr->height() + 1) / 2);
    }
    return rule;
}

SkySh project_sky_sh(const Sky& sky, const HemisphereRule& rule) {
    std::array<glm::dvec3, sh::kCount> acc{};
    for_each_sky_node(rule, true, [&](const glm::dvec3& d, double w) {
        const glm::dvec3 l = glm::dvec3(sky.radiance(d)) * w;
        const sh::ShVec y = sh::eval(d);
        for (int i = 0; i < sh::kCount; ++i) acc[i] += l * y[i];
    });
    SkySh out{};
    for (int i = 0; i < sh::kCount; ++i) out[i] = Rgb(acc[i]);
    return out;
}

SkySh project_sky_sh(const Sky& sky) {
    // An HDR map does not change with the sun: project it once (its rule can be large).
    if (const auto* hdr = dynamic_cast<const HdrSky*>(&sky)) return hdr->cached_sh();
    return project_sky_sh(sky, default_sky_rule(sky));
}

Rgb reconstruct_sky_sh(const SkySh& coefficients, const glm::dvec3& dir) {
    const sh::ShVec y = sh::eval(dir);
    glm::dvec3 v(0.0);
    for (int i = 0; i < sh::kCount; ++i) v += glm::dvec3(coefficients[i]) * y[i];
    return Rgb(v);
}

}  // namespace ts::light
