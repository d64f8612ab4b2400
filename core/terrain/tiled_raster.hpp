#pragma once
// One float raster stored as fixed-size square tiles, each with a halo of copied neighbour
// texels, all tiles in one contiguous array. Any texel is found in O(1) by shifts (the tile
// size is a power of two), and a bilinear sample reads its 2x2 footprint from a single tile
// (the halo holds the right/bottom neighbours), so the hot path has no branches on tiles.
//
// Outside the raster (halo and padding of edge tiles) texels repeat the nearest edge texel
// (clamp to edge), so reads near the edge need no special case. NaN texels (voids) stay NaN.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/terrain/valid_bilinear.hpp"

namespace ts::terrain {

class TiledRaster {
public:
    TiledRaster() = default;
    // Tiles `flat` (row-major width x height). tile_size: a power of two >= 1; halo >= 1.
    // Filled by `threads` threads (0 = one per core).
    TiledRaster(const float* flat, int width, int height, int tile_size, int halo, int threads = 0);

    int width() const { return width_; }
    int height() const { return height_; }
    int tile_size() const { return 1 << shift_; }
    int halo() const { return halo_; }
    int tiles_x() const { return tiles_x_; }
    int tiles_y() const { return tiles_y_; }
    // Texels per stored tile row (tile size + 2 halos).
    int stride() const { return stride_; }
    std::size_t memory_bytes() const { return data_.size() * sizeof(float); }

    // Texel (col, row), 0 <= col < width, 0 <= row < height. O(1), no bounds check.
    float at(int col, int row) const { return *address(col, row); }
    float at_clamped(int col, int row) const {
        return at(std::clamp(col, 0, width_ - 1), std::clamp(row, 0, height_ - 1));
    }
    // Pointer to the texel inside its tile; p[1] and p[stride()] are its east and south
    // neighbours (up to `halo` texels beyond the tile are valid).
    const float* address(int col, int row) const {
        const int tx = col >> shift_, ty = row >> shift_;
        const std::size_t tile = std::size_t(ty) * std::size_t(tiles_x_) + std::size_t(tx);
        const int lc = col - (tx << shift_) + halo_;
        const int lr = row - (ty << shift_) + halo_;
        return data_.data() + tile * tile_texels_ + std::size_t(lr) * std::size_t(stride_) + std::size_t(lc);
    }
    // Bilinear interpolation at texel-centre coordinates (x = 0 is the centre of column 0),
    // clamped to the raster (x, y must be finite). NaN if any of the four texels is a void.
    float bilinear(float x, float y) const {
        x = std::clamp(x, 0.0f, float(width_ - 1));
        y = std::clamp(y, 0.0f, float(height_ - 1));
        const int c = int(x), r = int(y);
        const float fx = x - float(c), fy = y - float(r);
        const float* p = address(c, r);
        const float top = p[0] + (p[1] - p[0]) * fx;
        const float bottom = p[stride_] + (p[stride_ + 1] - p[stride_]) * fx;
        return top + (bottom - top) * fy;
    }
    // Bilinear interpolation that skips voids (blend_valid_corners), in double-precision
    // texel-centre coordinates clamped to the raster: NaN only where every weighted corner is a
    // void. The same surface, texel for texel, as a flat grid sampled the same way.
    float bilinear_valid(double x, double y) const {
        float fx, fy;
        const int c = valid_bilinear_corner(std::clamp(x, 0.0, double(width_ - 1)), width_, fx);
        const int r = valid_bilinear_corner(std::clamp(y, 0.0, double(height_ - 1)), height_, fy);
        // p[1] / p[stride_] exist even on a 1-texel axis: the halo repeats the edge texel.
        const float* p = address(c, r);
        return blend_valid_corners(p[0], p[1], p[stride_], p[stride_ + 1], fx, fy);
    }
    // A stored texel by tile and tile-local position, local_col/local_row in [-halo, tile_size + halo).
    float tile_texel(int tx, int ty, int local_col, int local_row) const {
        const std::size_t tile = std::size_t(ty) * std::size_t(tiles_x_) + std::size_t(tx);
        return data_[tile * tile_texels_ + std::size_t(local_row + halo_) * std::size_t(stride_) +
                     std::size_t(local_col + halo_)];
    }

private:
    int width_ = 0, height_ = 0;
    int shift_ = 0, halo_ = 0, stride_ = 0;
    int tiles_x_ = 0, tiles_y_ = 0;
    std::size_t tile_texels_ = 0;
    std::vector<float> data_;
};

}  // namespace ts::terrain
