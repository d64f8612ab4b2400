#pragma once
// The exponentiation study behind `terrashade bench sh`: for log vectors of growing magnitude
// (random scenes of 0..500 sphere blockers plus a height field, and pure shapes scaled to a
// given magnitude) the error of every method against the exact exponential and its cost.
#include <string>
#include <vector>

#include "core/sh/exp_method.hpp"
#include "core/sh/sh_exp.hpp"

namespace ts::bench {

// One method with its parameters, and a label naming them ("order=8", "threshold=1").
struct ExpConfig {
    sh::ExpMethod method;
    sh::ExpOptions options;
    std::string param;
};

// Every method with default options (param "default").
std::vector<ExpConfig> default_exp_configs(const sh::ExpOptions& options = {});
// A sweep of each method's accuracy knob: Taylor order 2..12 (taylor, dc_isolation),
// thresholds 0.125..4 (scaling_squaring, hybrid) and optimal_linear once.
std::vector<ExpConfig> sweep_exp_configs();

struct ExpStudyOptions {
    std::vector<int> blocker_counts = {0, 1, 2, 4, 8, 16, 32, 64, 128, 256, 500};
    std::vector<double> magnitudes = {0.25, 0.5, 1, 2, 4, 8, 16, 32, 64};
    int scenes = 16;                      // random vectors per blocker count / magnitude
    bool height_field = true;             // add a random height field to every scene
    double log_eps = -6.907755278982137;  // visibility floor, log(0.001)
    std::vector<ExpConfig> configs = default_exp_configs();
    double min_timing_seconds = 0.02;  // per method and case
    unsigned long long seed = 1;
};

struct ExpStudyRow {
    std::string kind;  // "scene" (blockers + height field) or "shape" (scaled DC-free shape)
    std::string method;
    std::string param;
    int blockers = 0;        // scene: blocker count
    double magnitude = 0.0;  // mean non-DC norm of the log vectors
    double dc = 0.0;         // mean DC coefficient
    double rms_error = 0.0;  // mean over vectors of |approx - exact| / sqrt(4 pi) (RMS over the sphere)
    double rms_error_max = 0.0;
    double rel_error = 0.0;  // mean |approx - exact| / |exact|
    double ns_per_exp = 0.0;
    double min_value = 0.0;  // smallest value of the reconstructed approximation (all vectors)
    double max_value = 0.0;  // largest
    double exact_min = 0.0;  // the same for the exact exp projected to order 4
    double exact_max = 0.0;
    int nonfinite = 0;  // vectors with a NaN or Inf coefficient (must stay 0)
    // scene only (else -1): RMS error against the true visibility of the scene (exp of the
    // un-truncated log, i.e. the product of the blockers' and the height field's visibility,
    // projected to order 4), and the same error for the exact exponential of the order-4 log.
    double truth_rms_error = -1.0;
    double exact_truth_rms_error = -1.0;
    // scene only: RMS error against the binary visibility (eps -> 0: 1 where nothing blocks,
    // else 0), which includes the floor's own leak of eps through every blocker.
    double binary_rms_error = -1.0;
};

std::vector<ExpStudyRow> run_exp_study(const ExpStudyOptions& options);

// CSV with a header line; the columns are the fields of ExpStudyRow.
std::string exp_study_csv(const std::vector<ExpStudyRow>& rows);

}  // namespace ts::bench
