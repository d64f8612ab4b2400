#include "core/render/pixel_sun_shading.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/terrain/smooth_surface.hpp"
#include "core/terrain/valid_bilinear.hpp"
#include "core/util/parallel_for.hpp"

namespace ts::render {

glm::vec3 slope_normal(const terrain::HeightGrid& g, const terrain::SurfaceSample& s, double y) {
    const int row = std::clamp(int(std::lround(y)), 0, g.height - 1);
    const double gx = s.dz_dcol / g.dx_m[std::size_t(row)], gy = -s.dz_drow / g.dy_m[std::size_t(row)];
    const double len = std::sqrt(gx * gx + gy * gy + 1.0);
    return std::isfinite(len) ? glm::vec3(float(-gx / len), float(-gy / len), float(1.0 / len)) : glm::vec3(0, 0, 1);
}

PixelSunShading::PixelSunShading(const terrain::HeightGrid& grid, const SurfaceMarch* march, const TexelSunTerm& term,
                                 double sun_cos_radius, double curvature)
    : grid_(grid),
      // Rays only while the sun gives light.
      march_(march && term.terrain_visibility &&
                     term.irradiance_over_pi.x + term.irradiance_over_pi.y + term.irradiance_over_pi.z > 0.0f
                 ? march
                 : nullptr),
      term_(term),
      sun_radius_(std::acos(std::clamp(sun_cos_radius, -1.0, 1.0))),
      curvature_(curvature) {}

float PixelSunShading::uniform_visibility(int c0, int r0) const {
    // A shadow that slips between four texel centres is narrower than a texel: below what the
    // DEM resolves.
    const terrain::HeightGrid& g = grid_;
    const float* tv = term_.terrain_visibility;
    bool lit = false, dark = false;
    for (int r = r0; r <= std::min(r0 + 1, g.height - 1); ++r)
        for (int c = c0; c <= std::min(c0 + 1, g.width - 1); ++c) {
            const float v = tv[std::size_t(r) * g.width + c];
            if (v >= 0.999f)
                lit = true;
            else if (v <= 0.001f)
                dark = true;
            else
                return -1.0f;  // penumbra, or NaN
        }
    return lit == dark ? -1.0f : lit ? 1.0f : 0.0f;
}

void PixelSunShading::split(const glm::vec3* texel_radiance, std::size_t t, glm::vec3& rest, glm::vec3& weight) const {
    const TexelSunTerm& st = term_;
    const glm::vec3 s = st.direction;
    const bool water = st.water && st.water[t];
    const glm::vec3 albedo = water ? glm::vec3(0.0f) : glm::vec3(st.albedo_r[t], st.albedo_g[t], st.albedo_b[t]);
    const float v = st.visibility[t] == st.visibility[t] ? st.visibility[t] : 0.0f;
    const float cos_t = std::max(0.0f, st.nx[t] * s.x + st.ny[t] * s.y + st.nz[t] * s.z);
    rest = glm::max(texel_radiance[t] - albedo * (v * cos_t) * st.irradiance_over_pi, glm::vec3(0.0f));
    weight = march_ ? albedo : albedo * v;
}

void PixelSunShading::split_texels(const glm::vec3* texel_radiance, int threads) {
    const std::size_t n = std::size_t(grid_.width) * std::size_t(grid_.height);
    rest_.resize(n), weight_.resize(n);
    parallel_rows(grid_.height, threads, grid_.width * 16LL, [&](int r0, int r1) {
        for (std::size_t t = std::size_t(r0) * grid_.width; t < std::size_t(r1) * grid_.width; ++t)
            split(texel_radiance, t, rest_[t], weight_[t]);
    });
}

glm::vec3 PixelSunShading::radiance(const glm::vec3* texel_radiance, float x, float y, const glm::vec3& n) const {
    const terrain::HeightGrid& g = grid_;
    float fx = 0, fy = 0;
    const int c0 = terrain::valid_bilinear_corner(x, g.width, fx);
    const int r0 = terrain::valid_bilinear_corner(y, g.height, fy);
    const int c1 = std::min(c0 + 1, g.width - 1), r1 = std::min(r0 + 1, g.height - 1);
    const std::size_t corner[4] = {std::size_t(r0) * g.width + c0, std::size_t(r0) * g.width + c1,
                                   std::size_t(r1) * g.width + c0, std::size_t(r1) * g.width + c1};
    const float weight[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
    // The rest of each corner's radiance, bilinear, plus the sun's diffuse term with the
    // bilinear weight and this pixel's normal.
    const TexelSunTerm& st = term_;
    const glm::vec3 s = st.direction;
    glm::vec3 c(0.0f), w(0.0f);
    if (!rest_.empty()) {
        for (int q = 0; q < 4; ++q) c += weight[q] * rest_[corner[q]], w += weight[q] * weight_[corner[q]];
    } else {
        for (int q = 0; q < 4; ++q) {
            glm::vec3 rest, sun_weight;
            split(texel_radiance, corner[q], rest, sun_weight);
            c += weight[q] * rest, w += weight[q] * sun_weight;
        }
    }
    const float cos_p = std::max(0.0f, glm::dot(n, s));
    if (march_ && cos_p > 0) {
        const float uniform = uniform_visibility(c0, r0);
        float v =
            uniform >= 0 ? uniform : float(march_->sun_visible_fraction(x, y, glm::dvec3(s), sun_radius_, curvature_));
        if (st.blockers && v > 0) v *= float(st.blockers->visible(x, y, terrain::smooth_surface(g, x, y).z));
        w *= v;
    }
    return c + w * st.irradiance_over_pi * cos_p;
}

}  // namespace ts::render
