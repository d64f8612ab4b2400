#include "core/terrain/tiled_raster.hpp"

#include <bit>
#include <stdexcept>
#include <string>

#include "core/util/parallel_for.hpp"

namespace ts::terrain {

TiledRaster::TiledRaster(const float* flat, int width, int height, int tile_size, int halo, int threads)
    : width_(width), height_(height), halo_(halo) {
    if (width < 1 || height < 1) throw std::invalid_argument("TiledRaster: empty raster");
    if (tile_size < 1 || !std::has_single_bit(unsigned(tile_size))) {
        throw std::invalid_argument("TiledRaster: tile size " + std::to_string(tile_size) + " is not a power of two");
    }
    if (halo < 1 || halo > tile_size) throw std::invalid_argument("TiledRaster: halo must be in [1, tile size]");
    shift_ = std::countr_zero(unsigned(tile_size));
    stride_ = tile_size + 2 * halo;
    tiles_x_ = (width + tile_size - 1) / tile_size;
    tiles_y_ = (height + tile_size - 1) / tile_size;
    tile_texels_ = std::size_t(stride_) * std::size_t(stride_);
    data_.resize(tile_texels_ * std::size_t(tiles_x_) * std::size_t(tiles_y_));

    // One stored row of a tile = a clamped run of the source row: copy the in-range middle,
    // repeat the edge texel on either side.
    const int stored_rows = tiles_y_ * stride_;
    parallel_rows(stored_rows, threads, (long long)tiles_x_ * stride_, [&](int begin, int end) {
        for (int s = begin; s < end; ++s) {
            const int ty = s / stride_;
            const int lr = s % stride_;
            const int src_row = std::clamp((ty << shift_) + lr - halo_, 0, height_ - 1);
            const float* src = flat + std::size_t(src_row) * std::size_t(width_);
            for (int tx = 0; tx < tiles_x_; ++tx) {
                float* dst = data_.data() + (std::size_t(ty) * std::size_t(tiles_x_) + std::size_t(tx)) * tile_texels_ +
                             std::size_t(lr) * std::size_t(stride_);
                const int col0 = (tx << shift_) - halo_;
                const int lo = std::clamp(-col0, 0, stride_);                 // first local col inside the raster
                const int hi = std::clamp(width_ - col0, 0, stride_);         // one past the last inside
                for (int lc = 0; lc < lo; ++lc) dst[lc] = src[0];
                std::copy(src + col0 + lo, src + col0 + hi, dst + lo);
                for (int lc = hi; lc < stride_; ++lc) dst[lc] = src[width_ - 1];
            }
        }
    });
}

}  // namespace ts::terrain
