#pragma once
// The error statistics the bench commands report, in one place. The callers pick the samples
// (interior texels, valid pixels, a random subset) and drop the undefined ones; these
// functions only summarise. An empty sample gives NaN, which csv_number writes as an empty
// cell. Sums run in the order of the sample, so a report is reproducible bit for bit.
#include <span>
#include <vector>

namespace ts::bench {

// sqrt(sum e^2 / n).
double rmse(std::span<const double> errors);
// sum v / n.
double mean(std::span<const double> values);
// The smallest and the largest value (not magnitude: pass |e| for a largest absolute error).
double min_value(std::span<const double> values);
double max_value(std::span<const double> values);
// max |a_i - b_i| over paired values (0 for none; a NaN pair is skipped).
double max_abs_difference(std::span<const double> a, std::span<const double> b);
// The q-quantile (0 <= q <= 1) as the value of rank min(n - 1, floor(q n)) in ascending order
// (no interpolation). Reorders `values` (std::nth_element).
double percentile(std::vector<double>& values, double q);
// The median, the mean of the two middle values for an even count (timings of a few runs).
double median(std::vector<double> values);

// RMSE and 99th percentile of a sample of absolute errors.
struct AbsoluteErrors {
    double rmse, p99;
};
AbsoluteErrors absolute_errors(std::vector<double> abs_errors);

// got against ref, relative to the reference's mean: rmse = RMSE / mean(ref), bias =
// mean(got - ref) / mean(ref); p99 = 99th percentile of |got - ref| / ref over ref > 0.
// All NaN when the sample is empty or mean(ref) is not positive.
struct RelativeErrors {
    double rmse, p99, bias;
};
RelativeErrors relative_errors(std::span<const double> got, std::span<const double> ref);
// The largest |got_i - ref_i| / |ref_i| over |ref_i| > min_abs_ref (0 for none).
double max_relative_error(std::span<const double> got, std::span<const double> ref, double min_abs_ref);

// Two fields of fractions in [0, 1] (a sun-visible fraction per texel) compared as shadow masks
// (fraction < 0.5 is shadow) and as fractions, over the texels where both are defined.
struct MaskAgreement {
    long both_shadow = 0, either_shadow = 0, differ = 0;
    long reference_shadow = 0, test_shadow = 0;
    long compared = 0;      // texels where both are defined
    long nan_mismatch = 0;  // texels defined in one field only
    double abs_difference_sum = 0;

    void add(float reference, float test);
    // Intersection over union of the shadows; 1 when neither field has any.
    double iou() const;
    // Share of the compared texels whose masks differ; NaN when none compared.
    double disagreement() const;
    // Mean |reference - test| of the fractions; NaN when none compared.
    double mean_abs_difference() const;
    // Share of the compared texels in the reference's shadow; NaN when none compared.
    double reference_shadow_share() const;
};

}  // namespace ts::bench
