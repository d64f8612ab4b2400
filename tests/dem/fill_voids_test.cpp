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

namespace {
// A tilted plane with a nodata collar: the texels west of a diagonal line from (collar, 0) to
// (0, collar) are nodata, as in a corner of a gdalwarp copy.
Dem plane_with_collar(int n, int collar) {
    Dem d = plane_with_hole(n, 0, 0);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c)
            if (c + r < collar) d.z[d.index(c, r)] = NAN, d.void_mask[d.index(c, r)] = 1;
    return d;
}
void punch(Dem& d, int c0, int r0, int c1, int r1) {  // [c0, c1) x [r0, r1) nodata
    for (int r = r0; r < r1; ++r)
        for (int c = c0; c < c1; ++c) d.z[d.index(c, r)] = NAN, d.void_mask[d.index(c, r)] = 1;
}
}  // namespace

TEST(FillVoids, BorderConnectedNodataStaysOutsideAndEnclosedHolesAreFilled) {
    Dem d = plane_with_collar(40, 12);  // 78 collar texels
    punch(d, 25, 25, 29, 28);           // a 4x3 hole enclosed by data
    const VoidFillStats s = fill_voids(d);
    EXPECT_EQ(s.outside_texels, 78u);
    EXPECT_EQ(s.filled_texels, 12u);
    EXPECT_EQ(s.holes_filled, 1u);
    EXPECT_EQ(s.holes_unfilled, 0u);
    for (int r = 0; r < 40; ++r)
        for (int c = 0; c < 40; ++c) {
            if (c + r < 12) {
                EXPECT_TRUE(std::isnan(d.at(c, r))) << c << "," << r;  // outside: not filled
                EXPECT_TRUE(d.is_void(c, r));
            } else {
                EXPECT_NEAR(d.at(c, r), 100 + 2 * c + r, 0.05) << c << "," << r;  // measured or filled as the plane
            }
        }
    const VoidKinds k = classify_voids(plane_with_collar(40, 12));
    EXPECT_EQ(k.outside_texels, 78u);
    EXPECT_EQ(k.hole_texels, 0u);
}

// The flood is 4-connected: a hole that touches the collar only at a corner (the measured
// texels around it close a ring with a diagonal step) is enclosed and filled.
TEST(FillVoids, AHoleMeetingTheCollarAtACornerIsEnclosed) {
    Dem d = plane_with_collar(20, 6);  // collar texels c + r < 6
    punch(d, 4, 3, 6, 5);              // (4,3) meets collar texel (3,2) diagonally, no edge shared
    const VoidFillStats s = fill_voids(d);
    EXPECT_EQ(s.outside_texels, 21u);
    EXPECT_EQ(s.filled_texels, 4u);
    for (int r = 3; r < 5; ++r)
        for (int c = 4; c < 6; ++c) EXPECT_FALSE(std::isnan(d.at(c, r))) << c << "," << r;
}

TEST(FillVoids, AHoleWiderThanTheMaxDistanceIsLeftOutside) {
    // A 16x16 hole: its middle texels are 8 texels from the rim (Chebyshev, through the hole).
    Dem wide = plane_with_hole(40, 10, 26);
    const VoidFillStats s = fill_voids(wide, {.max_distance = 7});
    EXPECT_EQ(s.holes_unfilled, 1u);
    EXPECT_EQ(s.unfilled_texels, 256u);
    EXPECT_EQ(s.filled_texels, 0u);
    for (int r = 10; r < 26; ++r)
        for (int c = 10; c < 26; ++c) EXPECT_TRUE(std::isnan(wide.at(c, r)));  // left whole, not a ring
    Dem fits = plane_with_hole(40, 10, 26);
    EXPECT_EQ(fill_voids(fits, {.max_distance = 8}).filled_texels, 256u);
    Dem none = plane_with_hole(40, 10, 26);
    EXPECT_EQ(fill_voids(none, {.max_distance = 0}).filled_texels, 0u);
}

// The fill works on the voids, not the grid: the same collar-free hole in a grid 64 times larger
// costs exactly the same texel steps, and the steps are a bounded multiple of the hole's size.
TEST(FillVoids, TheWorkFollowsTheHolesNotTheGrid) {
    Dem small = plane_with_hole(64, 20, 30);
    Dem large = plane_with_hole(512, 20, 30);
    const VoidFillStats a = fill_voids(small), b = fill_voids(large);
    EXPECT_EQ(a.filled_texels, 100u);
    EXPECT_EQ(a.visited, b.visited);
    EXPECT_GT(a.visited, 100u);
    EXPECT_LE(a.visited, 100u * 502u);  // labelling + peel + at most 500 relaxation sweeps
    // A collar costs one step per collar texel, whatever the grid's size.
    Dem collar = plane_with_collar(512, 40);
    const VoidFillStats c = fill_voids(collar);
    EXPECT_EQ(c.visited, c.outside_texels);
}

TEST(FillVoids, FloorOutsideGivesTheCollarTheLowestHeight) {
    Dem d = plane_with_collar(20, 6);
    fill_voids(d);
    EXPECT_EQ(floor_outside(d), 21u);
    EXPECT_EQ(d.at(0, 0), 106.0f);  // the lowest measured height: 100 + 2*0 + 6 at (0, 6)
    EXPECT_TRUE(d.is_void(0, 0));
    EXPECT_EQ(floor_outside(d), 0u);
}
