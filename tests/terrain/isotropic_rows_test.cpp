// Rows of narrow texels averaged to square ones (core/terrain/isotropic_rows.hpp).
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/terrain/isotropic_rows.hpp"

namespace ts::terrain {
namespace {

TEST(IsotropicRows, RowsOfNarrowTexelsAreAveragedOverOneSquare) {
    // Row 0: texels 4x taller than wide (a box of 5); row 1: 1.9x (left alone); row 2: 2x (a box of 3).
    const int w = 8;
    std::vector<float> z(3 * w);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r * w + c)] = (c % 2) ? 10.0f : 0.0f;  // column stripes
    HeightGrid g = HeightGrid::uniform(w, 3, z, 1000, 4000);
    g.dx_m = {1000, 4000 / 1.9, 2000};
    EXPECT_EQ(isotropic_half_width(g, 0), 2);
    EXPECT_EQ(isotropic_half_width(g, 1), 0);
    EXPECT_EQ(isotropic_half_width(g, 2), 1);
    std::vector<float> out = z;
    make_rows_isotropic(g, out);
    // Row 0, texel 3: mean of texels 1..5 (10, 0, 10, 0, 10) = 6; the first texel: of 0..2.
    EXPECT_FLOAT_EQ(out[3], 6.0f);
    EXPECT_FLOAT_EQ(out[0], 10.0f / 3.0f);
    for (int c = 0; c < w; ++c) EXPECT_EQ(out[std::size_t(w + c)], z[std::size_t(w + c)]) << c;  // row 1 unchanged
    EXPECT_FLOAT_EQ(out[std::size_t(2 * w + 2)], 20.0f / 3.0f);  // row 2: texels 1..3
    // The stripes' contrast falls from 10 to under 2.5 in row 0.
    float lo = 1e9f, hi = -1e9f;
    for (int c = 2; c < w - 2; ++c) lo = std::min(lo, out[std::size_t(c)]), hi = std::max(hi, out[std::size_t(c)]);
    EXPECT_LT(hi - lo, 2.5f);
}

TEST(IsotropicRows, VoidsStayVoidsAndAreLeftOutOfTheirNeighboursAverages) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<float> z = {1, nan, 3, 5, 7};
    // 10:1 would be a box of 11; it is capped at the row's width (k = 2).
    HeightGrid g = HeightGrid::uniform(5, 1, z, 100, 1000);
    EXPECT_EQ(isotropic_half_width(g, 0), 2);
    std::vector<float> out = z;
    make_rows_isotropic(g, out);
    EXPECT_TRUE(std::isnan(out[1]));
    EXPECT_FLOAT_EQ(out[0], 2.0f);  // texels 0..2: 1 and 3
    EXPECT_FLOAT_EQ(out[2], 4.0f);  // texels 0..4: 1, 3, 5, 7
    EXPECT_FLOAT_EQ(out[4], 5.0f);  // texels 2..4: 3, 5, 7
}

TEST(IsotropicRows, SquareTexelsAreLeftAsTheyAre) {
    std::vector<float> z = {1, 9, 2, 8};
    const HeightGrid g = HeightGrid::uniform(4, 1, z, 30, 30);
    std::vector<float> out = z;
    make_rows_isotropic(g, out);
    EXPECT_EQ(out, z);
}

}  // namespace
}  // namespace ts::terrain
