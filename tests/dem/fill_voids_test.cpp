#include <cmath>

#include <gtest/gtest.h>

#include "core/dem/fill_voids.hpp"
#include "core/dem/statistics.hpp"
#include "core/util/error.hpp"

using namespace ts::dem;

namespace {
Dem plane_with_hole(int n, int hole_lo, int hole_hi) {
    Dem d;
    d.width = d.height = n;
    d.z.resize(std::size_t(n * n));
    d.void_mask.assign(d.z.size(), 0);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            const bool hole = c >= hole_lo && c < hole_hi && r >= hole_lo && r < hole_hi;
            d.z[d.index(c, r)] = hole ? NAN : float(100 + 2 * c + r);
            d.void_mask[d.index(c, r)] = hole ? 1 : 0;
        }
    d.georef = ts::geo::Georef(n, n, {0, 1, 0, double(n), 0, -1}, ts::geo::Crs::from_epsg(32633), true);
    return d;
}
}  // namespace

TEST(FillVoids, FillsAHoleInAPlaneCloseToThePlaneAndKeepsTheMask) {
    Dem d = plane_with_hole(40, 10, 26);
    const Dem before = d;
    fill_voids(d);
    EXPECT_EQ(d.void_count(), 16u * 16u);  // the mask still records the hole
    double worst = 0;
    for (int r = 0; r < 40; ++r)
        for (int c = 0; c < 40; ++c) {
            ASSERT_FALSE(std::isnan(d.at(c, r)));
            if (!before.is_void(c, r)) ASSERT_EQ(d.at(c, r), before.at(c, r));  // measured cells untouched
            else worst = std::max(worst, std::abs(double(d.at(c, r)) - (100 + 2 * c + r)));
        }
    // A plane is harmonic, so the relaxed fill converges to it; relaxation stops when no cell
    // moves by 1 mm, leaving ~0.5 mm here. 5 cm is far below the 5 m a bare peel leaves.
    EXPECT_LT(worst, 0.05);
}

TEST(FillVoids, AllVoidThrows) {
    Dem d = plane_with_hole(4, 0, 4);
    EXPECT_THROW(fill_voids(d), ts::InputError);
}

TEST(Statistics, ExcludeVoids) {
    Dem d = plane_with_hole(4, 1, 3);
    const HeightStats s = height_stats(d);
    EXPECT_EQ(s.void_count, 4u);
    EXPECT_EQ(s.valid_count, 12u);
    EXPECT_EQ(s.min, 100.0);
    EXPECT_EQ(s.max, 109.0);
    double sum = 0;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            if (!d.is_void(c, r)) sum += 100 + 2 * c + r;
    EXPECT_DOUBLE_EQ(s.mean, sum / 12);
}
