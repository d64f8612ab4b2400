#include "core/util/angles.hpp"
#include "core/visibility/horizon_sh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/sh/sh_exp.hpp"
#include "core/sh/slice_projector.hpp"
#include "core/util/error.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "synthetic_terrain.hpp"

using namespace ts::visibility;
using ts::kPi;

TEST(HorizonSh, MatchesSliceProjectorPerTexel) {
    // Every texel's 16 coefficients are the projector's for its own D horizons. The projector
    // sums float products in float (a few ulp of the largest term, |log_eps| sqrt(4 pi) = 18
    // here, ulp 2e-6); log_sh_raster sums in double and rounds once (measured 4.8e-7 apart).
    auto t = ts::visibility::testing::make_terrain(20, 16, 30, 30, ts::visibility::testing::hills);
    HorizonOptions o;
    o.directions = 16;
    const HorizonSet set = compute_horizons(t.grid, o);
    const auto log_sh = log_sh_raster(set, -5.0f, 2);
    const ts::sh::SliceProjector projector(16);
    for (std::size_t texel : {std::size_t(0), std::size_t(77), set.texels() - 1}) {
        std::vector<float> sigma;
        for (int d = 0; d < 16; ++d) sigma.push_back(set.plane(d)[texel]);
        const auto expected = projector.project_horizons(sigma.data(), -5.0f);
        for (int i = 0; i < 16; ++i)
            EXPECT_NEAR(log_sh[std::size_t(i) * set.texels() + texel], expected[std::size_t(i)], 4e-6);
    }
}

TEST(HorizonSh, ExponentiatedVisibilityFollowsTheHorizon) {
    // The visible fraction of the sphere from the exponentiated SH, sqrt(4 pi) c_00 / (4 pi),
    // against the geometric (1 - sin sigma) / 2 for a constant horizon sigma, with the default
    // visibility floor eps = 0.1 (docs/visibility.md: smaller floors make order-4 log-SH too
    // sharp for the approximate exponentials). Order-4 SH blur the step at the horizon;
    // hybrid lands within 0.03 of the geometric fraction here (a wrong sign, slice order or
    // azimuth blend misses by 0.1 or more).
    double previous = 1.0;
    for (double sigma : {-0.2, 0.0, 0.35, 0.5}) {
        HorizonSet set;
        set.width = 1;
        set.height = 1;
        set.directions = 32;
        set.angle.assign(32, float(sigma));
        const auto log_sh = log_sh_raster(set);
        const auto vis = exp_sh_raster(log_sh, 1, ts::sh::ExpMethod::hybrid);
        float direct[16];
        ts::sh::sh_exp(ts::sh::ExpMethod::hybrid, log_sh.data(), direct);
        for (int i = 0; i < 16; ++i) EXPECT_EQ(vis[std::size_t(i)], direct[i]);
        const double fraction = vis[0] * std::sqrt(4 * kPi) / (4 * kPi);
        EXPECT_NEAR(fraction, 0.5 * (1 - std::sin(std::max(sigma, -0.2))), 0.03) << sigma;
        EXPECT_LT(fraction, previous) << sigma;
        previous = fraction;
    }
}

TEST(HorizonSh, VoidTexelIsNaNAndFewDirectionsRejected) {
    HorizonSet set;
    set.width = 2;
    set.height = 1;
    set.directions = 8;
    set.angle.assign(16, 0.1f);
    set.angle[1] = std::nanf("");  // texel 1, direction 0
    const auto log_sh = log_sh_raster(set);
    EXPECT_FALSE(std::isnan(log_sh[0]));
    EXPECT_TRUE(std::isnan(log_sh[1]));
    EXPECT_TRUE(std::isnan(exp_sh_raster(log_sh, 2, ts::sh::ExpMethod::hybrid)[1]));
    set.directions = 2;
    set.angle.resize(4);
    EXPECT_THROW(log_sh_raster(set), ts::InputError);
}
