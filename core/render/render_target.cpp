#include "core/render/render_target.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"

namespace ts::render {
namespace {

// Bilinear sample of a texel raster at texel-centre coordinates (x, y), clamped to the grid.
// Texels outside the terrain hold NaN: the weights are then renormalised over the corners that
// have radiance, so the terrain's edge keeps its own colour (NaN when no corner has any).
glm::vec3 sample(const std::vector<glm::vec3>& src, int sw, int sh, double x, double y) {
    x = std::clamp(x, 0.0, double(sw - 1));
    y = std::clamp(y, 0.0, double(sh - 1));
    const int x0 = std::min(int(x), sw - 1), x1 = std::min(x0 + 1, sw - 1);
    const int y0 = std::min(int(y), sh - 1), y1 = std::min(y0 + 1, sh - 1);
    const float fx = float(x - x0), fy = float(y - y0);
    auto at = [&](int c, int r) { return src[std::size_t(r) * std::size_t(sw) + std::size_t(c)]; };
    const glm::vec3 a = at(x0, y0), b = at(x1, y0), c = at(x0, y1), d = at(x1, y1);
    if (!std::isnan(a.x + b.x + c.x + d.x))  // every corner has radiance: the plain formula
        return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy;
    glm::vec3 sum(0.0f);
    float weight = 0;
    for (auto [v, wt] : {std::pair{a, (1 - fx) * (1 - fy)}, {b, fx * (1 - fy)}, {c, (1 - fx) * fy}, {d, fx * fy}})
        if (!std::isnan(v.x) && wt > 0) sum += v * wt, weight += wt;
    return weight > 0 ? sum / weight : glm::vec3(std::numeric_limits<float>::quiet_NaN());
}

geo::Georef scaled_georef(const geo::Georef& g, int w, int h) {
    if (w == g.width() && h == g.height()) return g;
    geo::GeoTransform t = g.transform();
    const double sx = double(g.width()) / w, sy = double(g.height()) / h;
    t.dx_col *= sx, t.dy_col *= sx, t.dx_row *= sy, t.dy_row *= sy;
    return geo::Georef(w, h, t, g.crs_ptr(), g.pixel_is_area());
}

}  // namespace

GridTarget::GridTarget(const geo::Georef& dem_georef, int width, int height, std::vector<std::uint8_t> outside)
    : grid_width_(dem_georef.width()),
      grid_height_(dem_georef.height()),
      georef_(scaled_georef(dem_georef, width > 0 ? width : dem_georef.width(),
                            height > 0 ? height : dem_georef.height())),
      same_size_(georef_.width() == grid_width_ && georef_.height() == grid_height_),
      outside_(std::move(outside)) {}

void GridTarget::mark_outside(LinearImage& image) const {
    if (outside_.empty() || !same_size_) return;
    image.alpha.assign(outside_.size(), 255);
    for (std::size_t k = 0; k < outside_.size(); ++k)
        if (outside_[k]) image.alpha[k] = 0, image.rgb[k] = glm::vec3(0.0f);
}

void GridTarget::shade_sun_per_pixel(const terrain::HeightGrid& grid, bool pixel_shadows, double curvature,
                                     int threads) {
    const int w = width(), h = height();
    if (same_size_ || (w <= grid_width_ && h <= grid_height_)) return;
    std::vector<glm::vec2> at(std::size_t(w) * std::size_t(h));
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const double x = texel_x(i), y = texel_y(j);
            // Transparent pixels (the texel under the centre outside the terrain) keep theirs.
            const int c = std::clamp(int(x + 0.5), 0, grid_width_ - 1), r = std::clamp(int(y + 0.5), 0, grid_height_ - 1);
            const bool outside = !outside_.empty() && outside_[std::size_t(r) * std::size_t(grid_width_) + std::size_t(c)];
            at[std::size_t(j) * w + i] = outside ? glm::vec2(-1.0f) : glm::vec2(float(x), float(y));
        }
    pixel_sun_ = std::make_unique<MapPixelSun>(grid, std::move(at), w, h, pixel_shadows, curvature, threads);
}

void GridTarget::compose(const std::vector<glm::vec3>& texel_radiance, const TexelSunTerm* sun_term,
                         const light::Sky& sky, LinearImage& image) {
    const int w = width(), h = height();
    image.width = w, image.height = h;
    image.alpha.clear();
    if (same_size_) {
        image.rgb = texel_radiance;
        mark_outside(image);
        return;
    }
    image.rgb.resize(std::size_t(w) * std::size_t(h));
    if (!outside_.empty()) image.alpha.assign(image.rgb.size(), 255);
    const bool per_pixel = pixel_sun_ && sun_term;
    if (per_pixel)
        pixel_sun_->shade(texel_radiance, *sun_term, std::cos(sky.sun().angular_radius_rad), image.rgb, shaded_);
    for (int j = 0; j < h; ++j) {
        const double y = texel_y(j);
        for (int i = 0; i < w; ++i) {
            const double x = texel_x(i);
            const std::size_t k = std::size_t(j) * w + i;
            if (!per_pixel || !shaded_[k]) image.rgb[k] = sample(texel_radiance, grid_width_, grid_height_, x, y);
            if (outside_.empty()) continue;
            // The texel under the pixel's centre decides, as ExtentTarget's coverage does.
            const int c = std::clamp(int(x + 0.5), 0, grid_width_ - 1), r = std::clamp(int(y + 0.5), 0, grid_height_ - 1);
            if (outside_[std::size_t(r) * std::size_t(grid_width_) + std::size_t(c)] || std::isnan(image.rgb[k].x))
                image.alpha[k] = 0, image.rgb[k] = glm::vec3(0.0f);
        }
    }
}

ExtentTarget::ExtentTarget(const dem::Dem& dem, const geo::Georef& target, int threads)
    : grid_width_(dem.width), grid_height_(dem.height), georef_(target), threads_(threads) {
    if (!target.valid() || target.width() < 1 || target.height() < 1)
        throw InputError("render extent: empty or without a CRS");
    const bool same_crs = dem.georef.crs().same_as(target.crs());
    const int w = target.width(), h = target.height();
    at_.assign(std::size_t(w) * std::size_t(h), glm::vec2(-1.0f));
    std::vector<std::size_t> covered_rows(std::size_t(h), 0);
    parallel_rows(h, threads, w * 64LL, [&](int r0, int r1) {
        for (int j = r0; j < r1; ++j)
            for (int i = 0; i < w; ++i) {
                const glm::dvec2 xy = target.pixel_to_crs(i + 0.5, j + 0.5);
                glm::dvec2 p;
                if (same_crs) {
                    p = dem.georef.crs_to_pixel(xy);
                } else {
                    const glm::dvec2 ll = target.crs().to_lonlat(xy);
                    if (!std::isfinite(ll.x) || !std::isfinite(ll.y)) continue;
                    p = dem.georef.lonlat_to_pixel(ll);
                }
                // Edge coordinates: the DEM covers [0, width] x [0, height].
                if (!(p.x >= 0 && p.y >= 0 && p.x <= dem.width && p.y <= dem.height)) continue;
                const int c = std::min(int(p.x), dem.width - 1), r = std::min(int(p.y), dem.height - 1);
                const std::size_t texel = std::size_t(r) * std::size_t(dem.width) + std::size_t(c);
                // Outside the terrain, or a filled hole: shown as a map shows no data.
                if (std::isnan(dem.z[texel]) || (!dem.void_mask.empty() && dem.void_mask[texel])) continue;
                at_[std::size_t(j) * std::size_t(w) + std::size_t(i)] = glm::vec2(p.x - 0.5, p.y - 0.5);
                ++covered_rows[std::size_t(j)];
            }
    });
    for (std::size_t n : covered_rows) covered_ += n;
}

void ExtentTarget::shade_sun_per_pixel(const terrain::HeightGrid& grid, bool pixel_shadows, double curvature,
                                       int threads) {
    if (!pixels_magnify(at_, width(), height())) return;
    pixel_sun_ = std::make_unique<MapPixelSun>(grid, at_, width(), height(), pixel_shadows, curvature, threads);
}

void ExtentTarget::compose(const std::vector<glm::vec3>& texel_radiance, const TexelSunTerm* sun_term,
                           const light::Sky& sky, LinearImage& image) {
    const int w = width(), h = height();
    image.width = w, image.height = h;
    image.rgb.resize(std::size_t(w) * std::size_t(h));
    image.alpha.resize(image.rgb.size());
    const bool per_pixel = pixel_sun_ && sun_term;
    if (per_pixel)
        pixel_sun_->shade(texel_radiance, *sun_term, std::cos(sky.sun().angular_radius_rad), image.rgb, shaded_);
    parallel_rows(h, threads_, w * 16LL, [&](int r0, int r1) {
        for (std::size_t k = std::size_t(r0) * w; k < std::size_t(r1) * w; ++k) {
            const glm::vec2 p = at_[k];
            if (p.x < -0.75f) {  // off the DEM (a pixel on it is at least -0.5)
                image.rgb[k] = glm::vec3(0.0f);
                image.alpha[k] = 0;
                continue;
            }
            if (!per_pixel || !shaded_[k]) image.rgb[k] = sample(texel_radiance, grid_width_, grid_height_, p.x, p.y);
            image.alpha[k] = 255;
            if (std::isnan(image.rgb[k].x)) image.rgb[k] = glm::vec3(0.0f), image.alpha[k] = 0;
        }
    });
}

CameraTarget::CameraTarget(const terrain::HeightGrid& grid, const geo::Georef& georef, const Camera& camera,
                           const PerspectiveOptions& options)
    : camera_(camera), view_(grid, georef, camera, options) {}

ViewDirections CameraTarget::view_directions() const {
    ViewDirections v;
    v.per_texel = view_.view_directions();
    return v;
}

void CameraTarget::compose(const std::vector<glm::vec3>& texel_radiance, const TexelSunTerm* sun_term,
                           const light::Sky& sky, LinearImage& image) {
    sky_table_.update(sky);
    const light::SunDisc disc = sky.sun();
    const double r = disc.angular_radius_rad;
    const glm::vec3 sun_radiance = disc.disc_irradiance() / float(std::numbers::pi * r * r);
    view_.compose(texel_radiance.data(), sun_term, sky_table_, glm::vec3(disc.direction), sun_radiance, std::cos(r), image.rgb);
    image.width = view_.width(), image.height = view_.height();
    image.alpha.clear();
}

}  // namespace ts::render
