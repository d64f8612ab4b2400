#include "core/util/angles.hpp"
#include "core/visibility/small_angle_trig.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace ts::visibility;
using ts::kPi;

TEST(SmallAngleTrig, PolynomialsMatchLibmOnQuarterPi) {
    // The stated bounds of small_angle_trig.hpp on |x| <= pi/4 (the Taylor truncation, 2.6e-14
    // and 1.0e-15, plus double rounding), against std::sin(x) / x and std::cos(x).
    double sinc_err = 0, cos_err = 0;
    const int n = 20000;
    for (int i = 0; i <= n; ++i) {
        const double x = (kPi / 4) * (2.0 * i / n - 1.0);
        const double sinc = x == 0.0 ? 1.0 : std::sin(x) / x;
        sinc_err = std::max(sinc_err, std::abs(sin_over_x(x * x) - sinc));
        cos_err = std::max(cos_err, std::abs(cos_from_square(x * x) - std::cos(x)));
    }
    EXPECT_LT(sinc_err, 5e-14);
    EXPECT_LT(cos_err, 5e-14);
    // Outside the range the truncation grows fast: the bound is not loose by orders of magnitude.
    const double x = kPi / 2;
    EXPECT_GT(std::abs(sin_over_x(x * x) - std::sin(x) / x), 1e-11);
}
