#include "core/light/hdr_sky.hpp"

#include <algorithm>
#include <numbers>
#include <cmath>
#include <cstdio>

#include "core/geo/azimuth.hpp"
#include "core/light/sky_sh.hpp"
#include "core/util/angles.hpp"

namespace ts::light {

HdrSky::HdrSky(raster::FloatImage image, std::string source, double rotation_deg, double scale,
               const glm::dvec3& sun_direction_enu)
    : image_(std::move(image)), source_(std::move(source)), rotation_deg_(rotation_deg), scale_(scale) {
    glm::dvec3 s = sun_direction_enu;
    const double len = std::sqrt(s.x * s.x + s.y * s.y + s.z * s.z);
    sun_.direction = (std::isfinite(len) && len > 0.0) ? s / len : glm::dvec3(0.0, 0.0, 1.0);
    sun_.irradiance = Rgb(0.0f);
    // Radiance is never negative or NaN: some tools leave such pixels in their maps.
    for (float& v : image_.rgb) {
        if (!std::isfinite(v) || v < 0.0f) v = 0.0f;
    }
}

glm::dvec2 HdrSky::map_coordinates(const glm::dvec3& dir) const {
    const double horizontal = std::hypot(dir.x, dir.y);
    const double elevation_deg = std::atan2(dir.z, horizontal) * 180.0 / kPi;
    const double azimuth_deg = horizontal > 0.0 ? geo::phi_to_azimuth_cw_from_north(std::atan2(dir.y, dir.x)) : 0.0;
    double u = 0.5 + (azimuth_deg - rotation_deg_) / 360.0;
    u -= std::floor(u);
    const double v = (90.0 - elevation_deg) / 180.0;
    return {u * image_.width, v * image_.height};
}

Rgb HdrSky::radiance(const glm::dvec3& dir) const {
    const glm::dvec2 p = map_coordinates(dir);
    const double fx = p.x - 0.5;
    const double fy = std::clamp(p.y - 0.5, 0.0, static_cast<double>(image_.height - 1));
    const double x0f = std::floor(fx);
    const double y0f = std::floor(fy);
    const double tx = fx - x0f;
    const double ty = fy - y0f;
    const int w = image_.width;
    const int x0 = ((static_cast<int>(x0f) % w) + w) % w;
    const int x1 = (x0 + 1) % w;
    const int y0 = static_cast<int>(y0f);
    const int y1 = std::min(y0 + 1, image_.height - 1);
    Rgb out(0.0f);
    for (int c = 0; c < 3; ++c) {
        const double top = (1.0 - tx) * image_.pixel(x0, y0)[c] + tx * image_.pixel(x1, y0)[c];
        const double bottom = (1.0 - tx) * image_.pixel(x0, y1)[c] + tx * image_.pixel(x1, y1)[c];
        out[c] = static_cast<float>(scale_ * ((1.0 - ty) * top + ty * bottom));
    }
    return out;
}

glm::dvec3 HdrSky::brightest_direction() const {
    std::size_t best = 0;
    double best_y = -1.0;
    for (std::size_t p = 0; p * 3 < image_.rgb.size(); ++p) {
        const float* c = &image_.rgb[p * 3];
        const double y = 0.2126729 * c[0] + 0.7151522 * c[1] + 0.0721750 * c[2];
        if (y > best_y) {
            best_y = y;
            best = p;
        }
    }
    const int col = static_cast<int>(best % static_cast<std::size_t>(image_.width));
    const int row = static_cast<int>(best / static_cast<std::size_t>(image_.width));
    const double azimuth = rotation_deg_ + ((col + 0.5) / image_.width - 0.5) * 360.0;
    const double elevation = 90.0 - (row + 0.5) / image_.height * 180.0;
    return geo::enu_direction(geo::azimuth_cw_from_north_to_phi(azimuth), elevation * kPi / 180.0);
}

const SkySh& HdrSky::cached_sh() const {
    std::call_once(sh_once_, [this] { sh_ = project_sky_sh(*this, default_sky_rule(*this)); });
    return sh_;
}

const SkySh& HdrSky::cached_diffuse_sh() const {
    std::call_once(diffuse_sh_once_, [this] { diffuse_sh_ = project_diffuse_sky_sh(*this, default_sky_rule(*this)); });
    return diffuse_sh_;
}

double HdrSky::lighting_detail_rad() const {
    return std::numbers::pi / std::max(1, image_.height);
}

std::string HdrSky::describe() const {
    char buf[96];
    std::snprintf(buf, sizeof buf, " (%dx%d), centre azimuth %.1f deg, scale %g", image_.width, image_.height,
                  rotation_deg_, scale_);
    return "HDR map " + source_ + buf;
}

}  // namespace ts::light
