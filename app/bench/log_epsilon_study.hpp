#pragma once
// The log-epsilon trade-off of the log-BRDF (and of the visibility floor): a small epsilon
// represents the clamped lobe faithfully in the primal domain but makes a large, sharp log
// function whose order-4 truncation rings; a large epsilon is smooth but leaks light from
// below the horizon. For each epsilon: the lobe's log-ZH, exponentiated (hybrid), compared
// with the order-4 projection of the true lobe.
#include <string>
#include <vector>

namespace ts::bench {

struct LogEpsilonRow {
    std::string lobe;  // "diffuse", "phong10", "phong100", or "sphere" (a 20 deg sphere blocker)
    double eps = 0.0;
    double magnitude = 0.0;  // non-DC norm of the log vector
    double rms_error = 0.0;  // |exp*(f_log) - proj(true)| / sqrt(4 pi)
    double albedo = 0.0;     // integral of the exponentiated lobe (true: 1); for "sphere": visible fraction
    double albedo_true = 0.0;
    double lower_leak = 0.0;  // integral over the lower hemisphere of |reconstruction| (true: 0)
};

std::vector<LogEpsilonRow> run_log_epsilon_study(const std::vector<double>& eps_values);

// The visibility floor: random scenes (blockers + height field, as in exp_study.hpp) with log
// visibility log_eps, exponentiated with the hybrid method, against the binary visibility
// (eps -> 0). Rows have lobe "vis_<blockers>", rms_error that error, albedo fields 0.
std::vector<LogEpsilonRow> run_visibility_epsilon_study(const std::vector<double>& eps_values,
                                                        const std::vector<int>& blocker_counts, int scenes);
std::string log_epsilon_csv(const std::vector<LogEpsilonRow>& rows);

}  // namespace ts::bench
