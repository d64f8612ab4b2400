#include <gtest/gtest.h>

#include <cmath>

#include "app/bench/study/optimal_linear_fit.hpp"
#include "core/sh/sh_exp.hpp"

namespace ts::sh {
namespace {

TEST(OptimalLinear, CommittedTableIsReproducible) {
    // Refit a subset of the magnitudes (every 16th row: the same shapes, the same seed) and
    // compare with the committed table; the table prints 9 significant digits.
    OptimalLinearFitOptions o;
    const int stride = 16;
    o.steps = o.steps / stride;
    const auto rows = fit_optimal_linear(o);
    for (const OptimalLinearRow& r : rows) {
        const LinearCoeffs c = optimal_linear_coeffs(static_cast<float>(r.magnitude));
        EXPECT_NEAR(c.a, r.a, 1e-5 * std::max(1.0, std::abs(r.a))) << r.magnitude;
        EXPECT_NEAR(c.b, r.b, 1e-5 * std::max(1.0, std::abs(r.b))) << r.magnitude;
    }
}

TEST(OptimalLinear, StartsAtTheTaylorLinearTerm) {
    const LinearCoeffs c = optimal_linear_coeffs(0.0f);
    EXPECT_NEAR(c.a, 1.0f, 1e-6);
    EXPECT_NEAR(c.b, 1.0f, 1e-6);
}

}  // namespace
}  // namespace ts::sh
