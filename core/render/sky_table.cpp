#include "core/render/sky_table.hpp"

#include <algorithm>
#include <cmath>

#include "core/util/angles.hpp"

namespace ts::render {

SkyTable::SkyTable(int width, int height)
    : width_(std::max(width, 4)), height_(std::max(height, 2)), radiance_(std::size_t(width_) * height_, glm::vec3(0.0f)) {}

void SkyTable::update(const light::Sky& sky) {
    for (int j = 0; j < height_; ++j) {
        const double el = kPi / 2 - kPi * (j + 0.5) / height_;
        for (int i = 0; i < width_; ++i) {
            const double phi = -kPi + 2 * kPi * (i + 0.5) / width_;
            const glm::dvec3 d{std::cos(el) * std::cos(phi), std::cos(el) * std::sin(phi), std::sin(el)};
            radiance_[std::size_t(j) * width_ + i] = sky.radiance(d);
        }
    }
}

glm::vec3 SkyTable::lookup(const glm::vec3& d) const {
    constexpr float pi = float(kPi);
    const float phi = std::atan2(d.y, d.x);
    const float el = std::asin(std::clamp(d.z, -1.0f, 1.0f));
    const float u = (phi + pi) / (2 * pi) * float(width_) - 0.5f;
    const float v = std::clamp((pi / 2 - el) / pi * float(height_) - 0.5f, 0.0f, float(height_ - 1));
    const int i0 = int(std::floor(u)), j0 = std::min(int(v), height_ - 1);
    const float fu = u - float(i0), fv = v - float(j0);
    const int ia = (i0 % width_ + width_) % width_, ib = (ia + 1) % width_;
    const int j1 = std::min(j0 + 1, height_ - 1);
    auto at = [&](int i, int j) { return radiance_[std::size_t(j) * width_ + i]; };
    const glm::vec3 top = at(ia, j0) * (1 - fu) + at(ib, j0) * fu;
    const glm::vec3 bottom = at(ia, j1) * (1 - fu) + at(ib, j1) * fu;
    return top * (1 - fv) + bottom * fv;
}

}  // namespace ts::render
