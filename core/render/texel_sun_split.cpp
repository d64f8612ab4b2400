#include "core/render/texel_sun_split.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/util/angles.hpp"
#include "core/visibility/sun_visibility.hpp"

namespace ts::render {

TexelSunSplitter::TexelSunSplitter(const Scene& scene, const SunState& sun, const light::Sky& sky)
    : materials_(scene.state().materials()),
      normals_(scene.state().normals()),
      sun_vis_(scene.renderer().sun_visibility()),
      horizon_(scene.renderer().sun_horizon()),
      sun_dir_(glm::vec3(sun_direction(sun))),
      e_over_pi_(sky.sun().irradiance * float(1.0 / kPi)),
      sun_radius_rad_(sky.sun().angular_radius_rad) {}

TexelSunLight TexelSunSplitter::operator()(std::size_t t, glm::vec3 radiance) const {
    const float band = float(visibility::kSunHorizonBandRad);
    TexelSunLight l;
    l.normal = {normals_.x[t], normals_.y[t], normals_.z[t]};
    const float v = std::isnan(sun_vis_[t]) ? 0.0f : sun_vis_[t];
    const float w = v * std::max(0.0f, glm::dot(l.normal, sun_dir_));
    glm::vec3 a = glm::vec3(materials_.albedo_r[t], materials_.albedo_g[t], materials_.albedo_b[t]) * e_over_pi_;
    // The frame's sun term, never more than its radiance (a water or glossy texel's rest
    // holds its own sun); where that bound bites, a is lowered so the split still adds up.
    const glm::vec3 part = glm::min(a * w, radiance);
    if (w > 0) a = part / w;
    l.rest = radiance - part;
    l.sun_albedo = a;
    float h = t < horizon_.size() ? horizon_[t] : float(visibility::horizon_above_sun_for_fraction(v, sun_radius_rad_));
    if (std::isnan(sun_vis_[t]) || std::isnan(h)) h = band;
    l.horizon_above_sun = std::clamp(h, -band, band);
    return l;
}

}  // namespace ts::render
