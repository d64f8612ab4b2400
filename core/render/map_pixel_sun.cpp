#include "core/render/map_pixel_sun.hpp"

#include <algorithm>
#include <cmath>

#include "core/util/parallel_for.hpp"

namespace ts::render {
namespace {

bool on_dem(const glm::vec2& p) {
    return p.x >= -0.75f;
}

}  // namespace

bool pixels_magnify(const std::vector<glm::vec2>& at, int width, int height) {
    double along_rows = 0, along_columns = 0;
    std::size_t n_rows = 0, n_columns = 0;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const glm::vec2 p = at[std::size_t(j) * width + i];
            if (!on_dem(p)) continue;
            if (i + 1 < width && on_dem(at[std::size_t(j) * width + i + 1]))
                along_rows +=
                    std::hypot(at[std::size_t(j) * width + i + 1].x - p.x, at[std::size_t(j) * width + i + 1].y - p.y),
                    ++n_rows;
            if (j + 1 < height && on_dem(at[std::size_t(j + 1) * width + i]))
                along_columns +=
                    std::hypot(at[std::size_t(j + 1) * width + i].x - p.x, at[std::size_t(j + 1) * width + i].y - p.y),
                    ++n_columns;
        }
    return (n_rows && along_rows / double(n_rows) < 1.0) || (n_columns && along_columns / double(n_columns) < 1.0);
}

MapPixelSun::MapPixelSun(const terrain::HeightGrid& grid, std::vector<glm::vec2> at, int width, int height,
                         bool pixel_shadows, double curvature, int threads)
    : grid_(grid), at_(std::move(at)), width_(width), height_(height), curvature_(curvature), threads_(threads) {
    normal_.assign(at_.size(), glm::vec3(0, 0, 1));
    const float xmax = float(grid.width - 1), ymax = float(grid.height - 1);
    parallel_rows(height_, threads, width_ * 64LL, [&](int j0, int j1) {
        for (std::size_t k = std::size_t(j0) * width_; k < std::size_t(j1) * width_; ++k) {
            glm::vec2& p = at_[k];
            if (!on_dem(p)) continue;
            // Pixels on the outer half texel take the edge texel's centre line, as the blend does.
            p = glm::vec2(std::clamp(p.x, 0.0f, xmax), std::clamp(p.y, 0.0f, ymax));
            // The smoothed slope: Catmull-Rom's creases along the texel lines drew every texel
            // as a bump (an egg-crate texture on a noisy DEM).
            normal_[k] = slope_normal(grid, terrain::smooth_slope(grid, p.x, p.y), p.y);
        }
    });
    if (pixel_shadows) march_ = std::make_unique<SurfaceMarch>(grid, threads);
}

void MapPixelSun::shade(const std::vector<glm::vec3>& texel_radiance, const TexelSunTerm& term, double sun_cos_radius,
                        std::vector<glm::vec3>& rgb, std::vector<std::uint8_t>& shaded) const {
    PixelSunShading sun(grid_, march_.get(), term, sun_cos_radius, curvature_);
    sun.split_texels(texel_radiance.data(), threads_);
    const terrain::HeightGrid& g = grid_;
    rgb.resize(at_.size());
    shaded.assign(at_.size(), 0);
    parallel_rows(height_, threads_, width_ * (sun.marches() ? 200LL : 30LL), [&](int j0, int j1) {
        for (std::size_t k = std::size_t(j0) * width_; k < std::size_t(j1) * width_; ++k) {
            const glm::vec2 p = at_[k];
            if (!on_dem(p)) continue;
            // Every corner with radiance (voids and the terrain's outside hold NaN).
            const int c0 = std::min(int(p.x), std::max(g.width - 2, 0)),
                      r0 = std::min(int(p.y), std::max(g.height - 2, 0));
            const int c1 = std::min(c0 + 1, g.width - 1), r1 = std::min(r0 + 1, g.height - 1);
            const float sum =
                texel_radiance[std::size_t(r0) * g.width + c0].x + texel_radiance[std::size_t(r0) * g.width + c1].x +
                texel_radiance[std::size_t(r1) * g.width + c0].x + texel_radiance[std::size_t(r1) * g.width + c1].x;
            if (std::isnan(sum)) continue;
            rgb[k] = sun.radiance(texel_radiance.data(), p.x, p.y, normal_[k]);
            shaded[k] = 1;
        }
    });
}

}  // namespace ts::render
