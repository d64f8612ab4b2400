#include "core/render/open_sky_fraction.hpp"

#include <algorithm>
#include <string>

#include "core/render/tone_map.hpp"

namespace ts::render {
namespace {

// Radiance 1 above the horizon, nothing below, and a sun that gives no light.
class OpenHemisphereSky final : public light::Sky {
public:
    light::Rgb radiance(const glm::dvec3& d) const override { return light::Rgb(d.z > 0 ? 1.0f : 0.0f); }
    light::SunDisc sun() const override {
        light::SunDisc s;
        s.direction = glm::dvec3(0.0, 0.0, -1.0);
        s.irradiance = light::Rgb(0.0f);
        return s;
    }
    std::string describe() const override { return "uniform hemisphere (open-sky fraction)"; }
};

}  // namespace

std::vector<float> open_sky_fraction(FrameRenderer& frame) {
    const OpenHemisphereSky sky;
    std::vector<glm::vec3> radiance;
    frame.render(sky, SunState{0.0, -90.0}, radiance);
    const MaterialRaster& m = frame.state().materials();
    // The frame's transfer carries the bounced light too (T_d + T_b): the sky alone is without it.
    const std::vector<float>& bounce = frame.state().bounce_transfer();
    const std::size_t k_count = std::size_t(frame.state().bounce_coefficients());
    const light::SkySh sh = bounce.empty() ? light::SkySh{} : light::project_diffuse_sky_sh(sky);
    std::vector<float> out(radiance.size(), 1.0f);
    for (std::size_t t = 0; t < radiance.size(); ++t) {
        if (m.water[t]) continue;
        const float albedo = luminance(glm::vec3(m.albedo_r[t], m.albedo_g[t], m.albedo_b[t]));
        float v = luminance(radiance[t]) / albedo;
        if (!bounce.empty())
            for (std::size_t i = 0; i < k_count; ++i) {
                const float b = bounce[i * radiance.size() + t];
                if (b == b) v -= b * sh[i].g;  // a grey sky: every channel alike
            }
        if (albedo > 0.0f && v == v) out[t] = std::clamp(v, 0.0f, 1.0f);
    }
    return out;
}

}  // namespace ts::render
