// Stability on the global ETOPO1 grid (1 degree, 361 x 181 texel centres from -180 to 180 and
// from 90 to -90): the rows at the poles, where the east-west spacing collapses to zero, and
// the antimeridian, where the grid's first and last columns are the same meridian.
// Expected: every receiver a finite svf in [0, 1]; near the poles and across the antimeridian
// the exact and pyramid methods stay within a bounded error of the raymarch reference.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/dem/crop.hpp"
#include "core/dem/read_dem.hpp"
#include "core/util/error.hpp"
#include "core/visibility/visibility_grid.hpp"
#include "tests/stability/stability_support.hpp"

namespace ts::stability {
namespace {

using visibility::HorizonMethod;

const std::string kEtopo = std::string(TS_SHARED_DATA) + "/dem/etopo1_global_1deg.tif";

TEST(StabilityGlobalGrid, EveryReceiverOfTheGlobeHasFiniteSvfInRangeIncludingThePoleRows) {
    const dem::Dem d = dem::read_dem(kEtopo);
    const visibility::VisibilityGrid grid(d);
    for (HorizonMethod m : {HorizonMethod::exact, HorizonMethod::pyramid}) {
        const auto svf = method_svf(grid.view(), m, 16);
        long bad = 0;
        for (float v : svf)
            if (!(v >= 0.0f && v <= 1.0f)) ++bad;
        EXPECT_EQ(bad, 0) << visibility::method_name(m) << ": svf NaN or outside [0, 1]";
    }
}

// svf of a window of the global grid by `m` against the raymarch, both with blockers from the
// whole globe.
SvfComparison window_error(const terrain::HeightGrid& g, HorizonMethod m, visibility::ReceiverWindow w) {
    auto o = horizon_options(m, 32);
    o.window = w;
    auto ro = horizon_options(HorizonMethod::raymarch, 128);
    ro.window = w;
    const auto got = visibility::svf_raster(visibility::compute_horizons(g, o));
    const auto want = visibility::svf_raster(visibility::compute_horizons(g, ro));
    return compare_svf(got, want, w.width, w.height, /*skip_edge=*/false);
}

TEST(StabilityGlobalGrid, PoleRowsStayCloseToTheRaymarch) {
    // Rows 0..5 (90N..85N) and the last 6 (85S..90S), a 40-column stretch: the east-west
    // spacing goes from 9.7 km to zero there. Bounds with margin over the measured errors.
    const dem::Dem d = dem::read_dem(kEtopo);
    const visibility::VisibilityGrid grid(d);
    for (HorizonMethod m : {HorizonMethod::exact, HorizonMethod::pyramid})
        for (int row0 : {0, d.height - 6}) {
            const SvfComparison s = window_error(grid.view(), m, {160, row0, 40, 6});
            EXPECT_EQ(s.nan, 0) << visibility::method_name(m) << " rows from " << row0;
            EXPECT_EQ(s.out_of_range, 0) << visibility::method_name(m) << " rows from " << row0;
            EXPECT_LT(s.rmse, 0.02) << visibility::method_name(m) << " rows from " << row0;
        }
}

TEST(StabilityGlobalGrid, AntimeridianColumnsAreFiniteAndCloseToTheRaymarch) {
    // The grid does not wrap: the columns at -180 and +180 each see the globe on one side only
    // (an edge of the grid), so both are held to the edge's bound, and they agree with each
    // other (same meridian, same heights) within it.
    const dem::Dem d = dem::read_dem(kEtopo);
    const visibility::VisibilityGrid grid(d);
    for (HorizonMethod m : {HorizonMethod::exact, HorizonMethod::pyramid}) {
        for (int col0 : {0, d.width - 4}) {
            const SvfComparison s = window_error(grid.view(), m, {col0, 40, 4, 100});
            EXPECT_EQ(s.nan, 0) << visibility::method_name(m);
            EXPECT_EQ(s.out_of_range, 0) << visibility::method_name(m);
            EXPECT_LT(s.rmse, 0.02) << visibility::method_name(m) << " columns from " << col0;
        }
    }
}

TEST(StabilityGlobalGrid, ACropAcrossTheAntimeridianIsRefusedWithAClearMessage) {
    // --crop W,S,E,N with W > E (a box across 180) is a user error today: one line naming the
    // box, not a wrong crop.
    const dem::Dem d = dem::read_dem(kEtopo);
    try {
        (void)dem::crop(d, {170, -20, -170, 20});
        FAIL() << "a box across the antimeridian was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("W < E"), std::string::npos) << e.what();
    }
    // A box touching the pole is fine.
    const dem::Dem polar = dem::crop(d, {-30, 80, 30, 90});
    EXPECT_GT(polar.width, 0);
    const visibility::VisibilityGrid grid(polar);
    for (float v : method_svf(grid.view(), HorizonMethod::exact, 16)) ASSERT_TRUE(v >= 0.0f && v <= 1.0f);
}

}  // namespace
}  // namespace ts::stability
