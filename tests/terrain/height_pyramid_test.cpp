// HeightPyramid: every texel of every level, read through the tiles (and through halos at tile
// corners), equals the same 2x2 mean / max prefilter computed naively on whole grids.
#include "core/terrain/height_pyramid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include "tests/terrain/clamped_texel.hpp"

namespace ts::terrain {
namespace {

// An independent, deliberately plain reference: level i+1 texel = mean (or max) of the valid
// level-i texels among (2c..2c+1, 2r..2r+1) that exist.
struct NaiveLevel {
    int w, h;
    std::vector<float> mean, max;
};

std::vector<NaiveLevel> naive_pyramid(const std::vector<float>& z, int w, int h) {
    std::vector<NaiveLevel> levels{{w, h, z, z}};
    while (levels.back().w > 1 || levels.back().h > 1) {
        const NaiveLevel& p = levels.back();
        NaiveLevel n{(p.w + 1) / 2, (p.h + 1) / 2, {}, {}};
        for (int r = 0; r < n.h; ++r) {
            for (int c = 0; c < n.w; ++c) {
                double sum = 0;
                int count = 0;
                float best = -std::numeric_limits<float>::infinity();
                for (int dr = 0; dr < 2; ++dr)
                    for (int dc = 0; dc < 2; ++dc) {
                        const int sc = 2 * c + dc, sr = 2 * r + dr;
                        if (sc >= p.w || sr >= p.h) continue;
                        const float vm = p.mean[std::size_t(sr * p.w + sc)];
                        const float vx = p.max[std::size_t(sr * p.w + sc)];
                        if (!std::isnan(vm)) { sum += vm; ++count; }
                        if (!std::isnan(vx)) best = std::max(best, vx);
                    }
                n.mean.push_back(count ? float(sum / count) : std::nanf(""));
                n.max.push_back(count ? best : std::nanf(""));
            }
        }
        levels.push_back(std::move(n));
    }
    return levels;
}

std::vector<float> random_terrain(int w, int h, unsigned seed, double void_fraction) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> z(std::size_t(w) * std::size_t(h));
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            float v = 500.0f + 300.0f * std::sin(0.05f * float(c)) * std::cos(0.07f * float(r)) + 20.0f * u(rng);
            if (u(rng) < void_fraction) v = std::nanf("");
            z[std::size_t(r) * std::size_t(w) + std::size_t(c)] = v;
        }
    return z;
}

// Exactly equal, both NaN counting as equal: both sides sum in double (exact for four floats)
// and round once to float.
void expect_same(float got, float want, const char* what, int level, int c, int r) {
    if (std::isnan(want)) {
        ASSERT_TRUE(std::isnan(got)) << what << " level " << level << " at " << c << "," << r;
    } else {
        ASSERT_EQ(got, want) << what << " level " << level << " at " << c << "," << r;
    }
}

using test::clamped;

struct Size { int w, h, tile, halo; double voids; };
class PyramidSizes : public ::testing::TestWithParam<Size> {};

TEST_P(PyramidSizes, TiledLevelsEqualTheNaivePrefilterEverywhere) {
    const Size s = GetParam();
    const std::vector<float> z = random_terrain(s.w, s.h, unsigned(s.w * 31 + s.h), s.voids);
    const HeightGrid grid = HeightGrid::uniform(s.w, s.h, z, 30.0, 30.0);
    PyramidOptions options;
    options.tile_size = s.tile;
    options.halo = s.halo;
    options.threads = 2;
    const HeightPyramid pyramid(grid, options);
    const std::vector<NaiveLevel> naive = naive_pyramid(z, s.w, s.h);
    ASSERT_EQ(pyramid.level_count(), int(naive.size()));
    for (int i = 0; i < pyramid.level_count(); ++i) {
        const PyramidLevel& level = pyramid.level(i);
        const NaiveLevel& want = naive[std::size_t(i)];
        ASSERT_EQ(level.width, want.w);
        ASSERT_EQ(level.height, want.h);
        ASSERT_EQ(level.scale, 1 << i);
        for (int r = 0; r < want.h; ++r)
            for (int c = 0; c < want.w; ++c) {
                expect_same(level.at(c, r), want.mean[std::size_t(r * want.w + c)], "mean", i, c, r);
                expect_same(level.max_at(c, r), want.max[std::size_t(r * want.w + c)], "max", i, c, r);
            }
        // Halos and padding, including the four corners of every tile.
        for (const bool use_max : {false, true}) {
            const TiledRaster& t = use_max ? level.max_raster() : level.mean;
            const std::vector<float>& ref = use_max ? want.max : want.mean;
            const int T = t.tile_size(), H = t.halo();
            for (int ty = 0; ty < t.tiles_y(); ++ty)
                for (int tx = 0; tx < t.tiles_x(); ++tx)
                    for (int lr = -H; lr < T + H; ++lr)
                        for (int lc = -H; lc < T + H; ++lc)
                            expect_same(t.tile_texel(tx, ty, lc, lr), clamped(ref, want.w, want.h, tx * T + lc, ty * T + lr),
                                        use_max ? "max halo" : "mean halo", i, tx * T + lc, ty * T + lr);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(
    OddSizes, PyramidSizes,
    ::testing::Values(Size{3, 3, 256, 2, 0.0}, Size{3, 3, 2, 1, 0.2}, Size{361, 181, 64, 2, 0.0}, Size{361, 181, 32, 1, 0.05},
                      Size{1000, 1000, 256, 2, 0.01}, Size{1201, 1201, 256, 2, 0.0}, Size{1201, 37, 128, 3, 0.3}));

TEST(HeightPyramid, MaxIsAnUpperBoundOfEveryLevel0TexelBeneath) {
    const int w = 203, h = 150;
    const std::vector<float> z = random_terrain(w, h, 7, 0.02);
    const HeightPyramid p(HeightGrid::uniform(w, h, z, 1, 1), {.tile_size = 32, .halo = 1});
    for (int i = 1; i < p.level_count(); ++i) {
        const PyramidLevel& l = p.level(i);
        for (int r = 0; r < h; ++r)
            for (int c = 0; c < w; ++c) {
                const float v = z[std::size_t(r * w + c)];
                if (!std::isnan(v)) {
                    ASSERT_GE(l.max_at(c >> i, r >> i), v) << i;
                }
            }
    }
}

TEST(HeightPyramid, AllVoidBlocksAreNaNAndMixedBlocksAverageOnlyValidTexels) {
    // 4x2: left block all void, right block one valid texel of 10 and one of 20 (+2 voids).
    const float n = std::nanf("");
    const std::vector<float> z = {n, n, 10, n, n, n, n, 20};
    const HeightPyramid p(HeightGrid::uniform(4, 2, z, 1, 1));
    ASSERT_GE(p.level_count(), 2);
    EXPECT_TRUE(std::isnan(p.level(1).at(0, 0)));
    EXPECT_TRUE(std::isnan(p.level(1).max_at(0, 0)));
    EXPECT_FLOAT_EQ(p.level(1).at(1, 0), 15.0f);
    EXPECT_FLOAT_EQ(p.level(1).max_at(1, 0), 20.0f);
    EXPECT_FLOAT_EQ(p.level(2).at(0, 0), 15.0f);
}

TEST(HeightPyramid, LevelSpacingScalesWithTheLevelAndFollowsRows) {
    const int w = 8, h = 4;
    std::vector<float> z(std::size_t(w * h), 0.0f);
    HeightGrid g = HeightGrid::uniform(w, h, z, 0, 90);
    g.dx_m = {100, 90, 80, 70};  // shrinking eastward spacing, as towards a pole
    const HeightPyramid p(g);
    EXPECT_DOUBLE_EQ(p.level(1).dx_m[0], 2 * 95.0);
    EXPECT_DOUBLE_EQ(p.level(1).dx_m[1], 2 * 75.0);
    EXPECT_DOUBLE_EQ(p.level(2).dx_m[0], 4 * 85.0);
    EXPECT_DOUBLE_EQ(p.level(2).dy_m[0], 4 * 90.0);
}

TEST(HeightPyramid, SampleAtLevel0CoordinatesMatchesTexelCentres) {
    const int w = 64, h = 64;
    std::vector<float> z(std::size_t(w * h));
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r * w + c)] = float(3 * c + 5 * r);  // a plane
    const HeightPyramid p(HeightGrid::uniform(w, h, z, 1, 1), {.tile_size = 16, .halo = 1});
    // A plane is reproduced exactly by box means and bilinear interpolation away from edges.
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(p.level(i).sample_level0(20.25f, 30.5f), 3 * 20.25f + 5 * 30.5f, 1e-3f) << i;
    }
}

// A plain reference for sample_level0_valid: map to the level, clamp, then weight the (up to)
// four surrounding texels that exist and are not voids; NaN when no weighted texel is valid.
float naive_valid_sample(const NaiveLevel& l, int scale, double x0, double y0) {
    const double x = std::clamp((x0 + 0.5) / scale - 0.5, 0.0, double(l.w - 1));
    const double y = std::clamp((y0 + 0.5) / scale - 0.5, 0.0, double(l.h - 1));
    const int c = int(std::floor(x)), r = int(std::floor(y));
    double sum = 0, wsum = 0;
    for (int dr = 0; dr < 2; ++dr)
        for (int dc = 0; dc < 2; ++dc) {
            const double w = (dc ? x - c : 1 - (x - c)) * (dr ? y - r : 1 - (y - r));
            if (w <= 0 || c + dc >= l.w || r + dr >= l.h) continue;
            const float v = l.mean[std::size_t((r + dr) * l.w + c + dc)];
            if (!std::isnan(v)) sum += w * v, wsum += w;
        }
    return wsum > 1e-6 ? float(sum / wsum) : std::nanf("");
}

TEST(HeightPyramid, ValidSampleSkipsVoidsAndClampsAtEveryLevel) {
    // Odd sizes (a 1-texel-wide top level), tiles small enough that samples straddle tile
    // borders, and 20% voids so many footprints mix voids and heights.
    const int w = 45, h = 23;
    const std::vector<float> z = random_terrain(w, h, 7u, 0.2);
    const HeightPyramid p(HeightGrid::uniform(w, h, z, 30, 30), {.tile_size = 8, .halo = 1});
    const std::vector<NaiveLevel> naive = naive_pyramid(z, w, h);
    std::mt19937 rng(3);
    // Positions up to 3 texels beyond every edge, to check the clamping.
    std::uniform_real_distribution<double> ux(-3.0, w + 2.0), uy(-3.0, h + 2.0);
    int mixed = 0;
    for (int i = 0; i < p.level_count(); ++i) {
        for (int k = 0; k < 2000; ++k) {
            // Every 4th position exactly on a texel centre or an edge (fraction 0 or 1 cases).
            const double x0 = k % 4 == 0 ? double(k % (w + 2)) - 1 : ux(rng);
            const double y0 = k % 4 == 0 ? double(k % (h + 2)) - 1 : uy(rng);
            const float want = naive_valid_sample(naive[std::size_t(i)], 1 << i, x0, y0);
            const float got = p.level(i).sample_level0_valid(x0, y0);
            if (std::isnan(want)) {
                ASSERT_TRUE(std::isnan(got)) << "level " << i << " at " << x0 << "," << y0;
            } else {
                // Heights ~200..820 m; float rounding of the weights and sums stays far below 1e-3 m.
                ASSERT_NEAR(got, want, 1e-3f) << "level " << i << " at " << x0 << "," << y0;
                ++mixed;
            }
        }
    }
    EXPECT_GT(mixed, 1000);  // the comparison really ran on heights, not only on NaNs
    // A footprint whose only weighted corner is a void has no surface.
    std::vector<float> holes(16, 100.0f);
    holes[5] = std::nanf("");  // texel (1, 1)
    const HeightPyramid q(HeightGrid::uniform(4, 4, holes, 1, 1), {.tile_size = 2, .halo = 1});
    EXPECT_TRUE(std::isnan(q.level(0).sample_level0_valid(1.0, 1.0)));
    EXPECT_FLOAT_EQ(q.level(0).sample_level0_valid(1.5, 1.0), 100.0f);
}

TEST(HeightPyramid, OffsetMetricUsesRowSpacing) {
    const int w = 10, h = 10;
    std::vector<float> z(std::size_t(w * h), 0.0f);
    const HeightPyramid p(HeightGrid::uniform(w, h, z, 30, 90));
    float x = 0, y = 0;
    p.offset_metric(5, 5, 60, 180, x, y);
    EXPECT_FLOAT_EQ(x, 7.0f);
    EXPECT_FLOAT_EQ(y, 3.0f);  // north = towards row 0
}

TEST(HeightPyramid, RejectsBadOptions) {
    std::vector<float> z(9, 0.0f);
    const HeightGrid g = HeightGrid::uniform(3, 3, z, 1, 1);
    EXPECT_THROW(HeightPyramid(g, {.tile_size = 100}), std::invalid_argument);
    EXPECT_THROW(HeightPyramid(g, {.tile_size = 16, .halo = 0}), std::invalid_argument);
}

TEST(HeightPyramid, MaxLevelsStopsEarly) {
    std::vector<float> z(64 * 64, 1.0f);
    const HeightPyramid p(HeightGrid::uniform(64, 64, z, 1, 1), {.max_levels = 3});
    EXPECT_EQ(p.level_count(), 3);
}

}  // namespace
}  // namespace ts::terrain
