#pragma once
// Fits the optimal linear approximation exp(f_hat) ~ a(m) 1 + b(m) f_hat [Ren et al. 2006]
// for DC-free log vectors f_hat of magnitude m = |f_hat|: least squares over random shapes
// (log_scenes.hpp) scaled to m, against the exact exponential (exact_exp.hpp). Since
// <1, f_hat> = 0 the two unknowns decouple:
//   a(m) = mean_s g_s[0] / sqrt(4 pi),   b(m) = sum_s <g_s, f_s> / sum_s |f_s|^2,
// with g_s the exact exp coefficients. Deterministic for given options (fixed seed), so the
// committed table optimal_linear_table.inc is reproducible (scripts/fit_optimal_linear.sh).
#include <cstdint>
#include <string>
#include <vector>

namespace ts::sh {

struct OptimalLinearFitOptions {
    double max_magnitude = 32.0;
    int steps = 128;             // table rows: magnitudes 0, max/steps, ..., max
    int samples = 256;           // random shapes per magnitude (the same shapes for every m)
    std::uint64_t seed = 20061;  // Ren et al. 2006
};

struct OptimalLinearRow {
    double magnitude, a, b;
};

std::vector<OptimalLinearRow> fit_optimal_linear(const OptimalLinearFitOptions& options = {});
// The rows as C++ initialisers for optimal_linear_table.inc.
std::string format_optimal_linear_table(const std::vector<OptimalLinearRow>& rows,
                                        const OptimalLinearFitOptions& options);

}  // namespace ts::sh
