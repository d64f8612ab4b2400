// TiledRaster: every texel read through the tiles, and every stored halo/padding texel, equals
// the whole raster read with clamp-to-edge.
#include "core/terrain/tiled_raster.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include "tests/terrain/clamped_texel.hpp"

namespace ts::terrain {
namespace {

std::vector<float> ramp(int w, int h) {
    std::vector<float> v(std::size_t(w) * std::size_t(h));
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) v[std::size_t(r) * std::size_t(w) + std::size_t(c)] = float(r * 10007 + c);
    return v;
}

using test::clamped;

struct Case { int w, h, tile, halo; };

class TiledRasterSizes : public ::testing::TestWithParam<Case> {};

TEST_P(TiledRasterSizes, EveryTexelAndHaloMatchesTheWholeRaster) {
    const Case k = GetParam();
    const std::vector<float> flat = ramp(k.w, k.h);
    const TiledRaster t(flat.data(), k.w, k.h, k.tile, k.halo, 2);
    ASSERT_EQ(t.tiles_x(), (k.w + k.tile - 1) / k.tile);
    for (int r = 0; r < k.h; ++r)
        for (int c = 0; c < k.w; ++c) ASSERT_EQ(t.at(c, r), flat[std::size_t(r) * std::size_t(k.w) + std::size_t(c)]) << c << "," << r;
    // Every stored texel of every tile, halos and padding included.
    for (int ty = 0; ty < t.tiles_y(); ++ty)
        for (int tx = 0; tx < t.tiles_x(); ++tx)
            for (int lr = -k.halo; lr < k.tile + k.halo; ++lr)
                for (int lc = -k.halo; lc < k.tile + k.halo; ++lc)
                    ASSERT_EQ(t.tile_texel(tx, ty, lc, lr), clamped(flat, k.w, k.h, tx * k.tile + lc, ty * k.tile + lr))
                        << "tile " << tx << "," << ty << " local " << lc << "," << lr;
}

TEST_P(TiledRasterSizes, BilinearMatchesWholeRasterBilinear) {
    const Case k = GetParam();
    const std::vector<float> flat = ramp(k.w, k.h);
    const TiledRaster t(flat.data(), k.w, k.h, k.tile, k.halo, 1);
    // Positions straddling tile boundaries and the raster edges, and outside the raster.
    for (float y = -1.25f; y < float(k.h) + 0.5f; y += 0.75f) {
        for (float x = -1.25f; x < float(k.w) + 0.5f; x += 0.6f) {
            const float cx = std::clamp(x, 0.0f, float(k.w - 1)), cy = std::clamp(y, 0.0f, float(k.h - 1));
            const int c = int(cx), r = int(cy);
            const float fx = cx - float(c), fy = cy - float(r);
            const float expected = (1 - fy) * ((1 - fx) * clamped(flat, k.w, k.h, c, r) + fx * clamped(flat, k.w, k.h, c + 1, r)) +
                                   fy * ((1 - fx) * clamped(flat, k.w, k.h, c, r + 1) + fx * clamped(flat, k.w, k.h, c + 1, r + 1));
            // Float rounding of two lerp orders on values up to ~1e7: a few ulps.
            ASSERT_NEAR(t.bilinear(x, y), expected, std::abs(expected) * 4e-7f + 1e-3f) << x << "," << y;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Sizes, TiledRasterSizes,
                         ::testing::Values(Case{3, 3, 1, 1}, Case{3, 3, 2, 1}, Case{17, 9, 4, 2}, Case{64, 64, 16, 1},
                                           Case{101, 37, 32, 3}, Case{361, 181, 64, 2}));

TEST(TiledRaster, RejectsBadTiling) {
    const std::vector<float> flat(9, 1.0f);
    EXPECT_THROW(TiledRaster(flat.data(), 3, 3, 3, 1), std::invalid_argument);  // not a power of two
    EXPECT_THROW(TiledRaster(flat.data(), 3, 3, 4, 0), std::invalid_argument);  // no halo
    EXPECT_THROW(TiledRaster(flat.data(), 0, 3, 4, 1), std::invalid_argument);
}

TEST(TiledRaster, VoidsStayNaN) {
    std::vector<float> flat(25, 2.0f);
    flat[12] = std::nanf("");
    const TiledRaster t(flat.data(), 5, 5, 2, 1);
    EXPECT_TRUE(std::isnan(t.at(2, 2)));
    EXPECT_TRUE(std::isnan(t.bilinear(1.5f, 1.5f)));
    EXPECT_FLOAT_EQ(t.bilinear(0.5f, 0.5f), 2.0f);
}

}  // namespace
}  // namespace ts::terrain
