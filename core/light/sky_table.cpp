#include "core/light/sky_table.hpp"

#include <algorithm>
#include <cmath>

#include "core/util/angles.hpp"

namespace ts::light {

SkyGrid SkyGrid::whole_sphere(int azimuths, int elevations) {
    SkyGrid g;
    g.azimuths = std::max(azimuths, 4), g.elevations = std::max(elevations, 2);
    g.phi_begin = -kPi;
    g.first_el = kPi / 2, g.last_el = -kPi / 2;
    g.texel_centres = true;
    return g;
}

SkyTable::SkyTable(const SkyGrid& grid)
    : grid_(grid), radiance_(std::size_t(grid.azimuths) * std::size_t(grid.elevations), Rgb(0.0f)) {}

void SkyTable::update(const Sky& sky) {
    const int w = grid_.azimuths, h = grid_.elevations;
    const double o = grid_.texel_centres ? 0.5 : 0.0;
    const int rows = grid_.texel_centres ? h : h - 1;
    for (int j = 0; j < h; ++j) {
        const double el = grid_.first_el + (grid_.last_el - grid_.first_el) * (j + o) / rows;
        const double sample_el = std::max(el, grid_.lowest_sampled_el);
        for (int i = 0; i < w; ++i) {
            const double phi = grid_.phi_begin + 2 * kPi * (i + o) / w;
            const glm::dvec3 d{std::cos(sample_el) * std::cos(phi), std::cos(sample_el) * std::sin(phi),
                               std::sin(sample_el)};
            radiance_[std::size_t(j) * std::size_t(w) + std::size_t(i)] = sky.radiance(d);
        }
    }
}

glm::vec3 SkyTable::lookup(const glm::vec3& d) const {
    constexpr float pi = float(kPi);
    const int w = grid_.azimuths, h = grid_.elevations;
    const float o = grid_.texel_centres ? 0.5f : 0.0f;
    const int rows = grid_.texel_centres ? h : h - 1;
    const float phi = std::atan2(d.y, d.x);
    const float el = std::asin(std::clamp(d.z, -1.0f, 1.0f));
    const float first = float(grid_.first_el), last = float(grid_.last_el);
    const float u = (phi - float(grid_.phi_begin)) / (2 * pi) * float(w) - o;
    const float v = std::clamp((el - first) / (last - first) * float(rows) - o, 0.0f, float(h - 1));
    const int i0 = int(std::floor(u)), j0 = std::min(int(v), h - 1);
    const float fu = u - float(i0), fv = v - float(j0);
    const int ia = (i0 % w + w) % w, ib = (ia + 1) % w;
    const int j1 = std::min(j0 + 1, h - 1);
    auto at = [&](int i, int j) { return radiance_[std::size_t(j) * std::size_t(w) + std::size_t(i)]; };
    const glm::vec3 top = at(ia, j0) * (1 - fu) + at(ib, j0) * fu;
    const glm::vec3 bottom = at(ia, j1) * (1 - fu) + at(ib, j1) * fu;
    return top * (1 - fv) + bottom * fv;
}

}  // namespace ts::light
