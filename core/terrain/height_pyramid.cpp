#include "core/terrain/height_pyramid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/util/parallel_for.hpp"

namespace ts::terrain {

std::vector<float> downsample_2x2(const float* src, int w, int h, bool use_max, int threads) {
    const int ow = (w + 1) / 2, oh = (h + 1) / 2;
    std::vector<float> dst(std::size_t(ow) * std::size_t(oh));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    parallel_rows(oh, threads, ow, [&](int begin, int end) {
        for (int r = begin; r < end; ++r) {
            const int r0 = 2 * r, r1 = std::min(2 * r + 1, h - 1);
            const float* row0 = src + std::size_t(r0) * std::size_t(w);
            const float* row1 = src + std::size_t(r1) * std::size_t(w);
            const bool has_r1 = r1 != r0;
            for (int c = 0; c < ow; ++c) {
                const int c0 = 2 * c, c1 = 2 * c + 1;
                const bool has_c1 = c1 < w;
                float v[4];
                int n = 0;
                v[n++] = row0[c0];
                if (has_c1) v[n++] = row0[c1];
                if (has_r1) v[n++] = row1[c0];
                if (has_r1 && has_c1) v[n++] = row1[c1];
                // Sums of four floats are exact in double, so the mean is the correctly rounded one.
                double sum = 0.0;
                float best = -std::numeric_limits<float>::infinity();
                int valid = 0;
                for (int k = 0; k < n; ++k) {
                    if (std::isnan(v[k])) continue;
                    sum += v[k];
                    best = std::max(best, v[k]);
                    ++valid;
                }
                dst[std::size_t(r) * std::size_t(ow) + std::size_t(c)] =
                    valid == 0 ? nan : (use_max ? best : float(sum / double(valid)));
            }
        }
    });
    return dst;
}

namespace {

// Spacing of level rows: mean over the level-0 rows each covers, times the scale.
std::vector<double> level_spacing(const std::vector<double>& level0, int scale, int rows) {
    std::vector<double> out(static_cast<std::size_t>(rows));
    const int n0 = int(level0.size());
    for (int r = 0; r < rows; ++r) {
        const int begin = r * scale, end = std::min(n0, begin + scale);
        double sum = 0;
        for (int k = begin; k < end; ++k) sum += level0[std::size_t(k)];
        out[std::size_t(r)] = sum / double(end - begin) * double(scale);
    }
    return out;
}

}  // namespace

HeightPyramid::HeightPyramid(const HeightGrid& grid, const PyramidOptions& options) : options_(options) {
    if (grid.width < 1 || grid.height < 1) throw std::invalid_argument("HeightPyramid: empty grid");
    if (grid.z.size() != std::size_t(grid.width) * std::size_t(grid.height)) {
        throw std::invalid_argument("HeightPyramid: height array does not match the grid size");
    }
    if (options.tile_size < 1 || !std::has_single_bit(unsigned(options.tile_size))) {
        throw std::invalid_argument("HeightPyramid: tile_size must be a power of two");
    }
    if (options.halo < 1 || options.halo > options.tile_size) {
        throw std::invalid_argument("HeightPyramid: halo must be in [1, tile_size]");
    }
    if (options.max_levels < 0) throw std::invalid_argument("HeightPyramid: max_levels must be >= 0");
    level0_dx_m_ = grid.dx_m;
    level0_dy_m_ = grid.dy_m;
    if (level0_dx_m_.size() != std::size_t(grid.height)) level0_dx_m_.assign(std::size_t(grid.height), 1.0);
    if (level0_dy_m_.size() != std::size_t(grid.height)) level0_dy_m_.assign(std::size_t(grid.height), 1.0);

    // The level being tiled: level 0 reads the grid in place; coarser ones own their data.
    const float* current_mean = grid.z.data();
    const float* current_max = grid.z.data();  // the max of level 0 is the heights
    std::vector<float> mean, max;
    int w = grid.width, h = grid.height, scale = 1;
    for (int i = 0;; ++i) {
        PyramidLevel level;
        level.index = i;
        level.width = w;
        level.height = h;
        level.scale = scale;
        // Small levels get smaller tiles: a 2x2 level in a 256^2 tile would waste memory.
        const int tile = std::min(options.tile_size, int(std::bit_ceil(unsigned(std::max(w, h)))));
        const int halo = std::min(options.halo, tile);
        level.mean = TiledRaster(current_mean, w, h, tile, halo, options.threads);
        if (i > 0) level.max = TiledRaster(current_max, w, h, tile, halo, options.threads);
        level.dx_m = level_spacing(level0_dx_m_, scale, h);
        level.dy_m = level_spacing(level0_dy_m_, scale, h);
        levels_.push_back(std::move(level));
        const bool last = (w == 1 && h == 1) || (options.max_levels > 0 && i + 1 >= options.max_levels);
        if (last) break;
        max = downsample_2x2(current_max, w, h, true, options.threads);
        mean = downsample_2x2(current_mean, w, h, false, options.threads);
        current_max = max.data();
        current_mean = mean.data();
        w = (w + 1) / 2;
        h = (h + 1) / 2;
        scale *= 2;
    }
}

std::size_t HeightPyramid::memory_bytes() const {
    std::size_t bytes = 0;
    for (const PyramidLevel& l : levels_) bytes += l.mean.memory_bytes() + l.max.memory_bytes();
    return bytes;
}

void HeightPyramid::offset_metric(float x0, float y0, double east_m, double north_m, float& x, float& y) const {
    const int rows = int(level0_dy_m_.size());
    auto spacing_at = [&](const std::vector<double>& v, double row) {
        const int r = std::clamp(int(std::lround(row)), 0, rows - 1);
        return v[std::size_t(r)];
    };
    // Rows grow southwards. First guess with the start row's spacing, then redo with the mid row's.
    double dy = spacing_at(level0_dy_m_, y0);
    double y1 = y0 - north_m / dy;
    const double mid = 0.5 * (y0 + y1);
    dy = spacing_at(level0_dy_m_, mid);
    y1 = y0 - north_m / dy;
    const double dx = spacing_at(level0_dx_m_, 0.5 * (y0 + y1));
    x = float(x0 + east_m / dx);
    y = float(y1);
}

}  // namespace ts::terrain
