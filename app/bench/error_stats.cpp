#include "app/bench/error_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace ts::bench {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

double rmse(std::span<const double> errors) {
    if (errors.empty()) return kNaN;
    double se = 0;
    for (double e : errors) se += e * e;
    return std::sqrt(se / double(errors.size()));
}

double mean(std::span<const double> values) {
    if (values.empty()) return kNaN;
    double sum = 0;
    for (double v : values) sum += v;
    return sum / double(values.size());
}

double min_value(std::span<const double> values) {
    if (values.empty()) return kNaN;
    double m = values[0];
    for (double v : values) m = std::min(m, v);
    return m;
}

double max_value(std::span<const double> values) {
    if (values.empty()) return kNaN;
    double m = values[0];
    for (double v : values) m = std::max(m, v);
    return m;
}

double max_abs_difference(std::span<const double> a, std::span<const double> b) {
    double m = 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
    return m;
}

double percentile(std::vector<double>& values, double q) {
    if (values.empty()) return kNaN;
    const std::size_t k = std::min(values.size() - 1, std::size_t(q * double(values.size())));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
    return values[k];
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? kNaN : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

AbsoluteErrors absolute_errors(std::vector<double> abs_errors) {
    const double r = rmse(abs_errors);  // before percentile reorders the sample
    return {r, percentile(abs_errors, 0.99)};
}

RelativeErrors relative_errors(std::span<const double> got, std::span<const double> ref) {
    RelativeErrors r{kNaN, kNaN, kNaN};
    std::vector<double> error, relative;
    error.reserve(got.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        const double e = got[i] - ref[i];
        error.push_back(e);
        if (ref[i] > 0) relative.push_back(std::abs(e) / ref[i]);
    }
    const double ref_mean = mean(ref.first(got.size()));
    if (got.empty() || !(ref_mean > 0)) return r;
    r.rmse = rmse(error) / ref_mean;
    r.bias = mean(error) / ref_mean;
    r.p99 = percentile(relative, 0.99);
    return r;
}

double max_relative_error(std::span<const double> got, std::span<const double> ref, double min_abs_ref) {
    double m = 0;
    for (std::size_t i = 0; i < got.size() && i < ref.size(); ++i)
        if (std::abs(ref[i]) > min_abs_ref) m = std::max(m, std::abs(got[i] - ref[i]) / std::abs(ref[i]));
    return m;
}

void MaskAgreement::add(float reference, float test) {
    const bool nr = std::isnan(reference), nt = std::isnan(test);
    if (nr != nt) ++nan_mismatch;
    if (nr || nt) return;
    const bool sr = reference < 0.5f, st = test < 0.5f;
    both_shadow += sr && st;
    either_shadow += sr || st;
    differ += sr != st;
    reference_shadow += sr;
    test_shadow += st;
    abs_difference_sum += std::abs(double(reference) - test);
    ++compared;
}

double MaskAgreement::iou() const {
    return either_shadow > 0 ? double(both_shadow) / double(either_shadow) : 1.0;
}

double MaskAgreement::disagreement() const {
    return compared > 0 ? double(differ) / double(compared) : kNaN;
}

double MaskAgreement::mean_abs_difference() const {
    return compared > 0 ? abs_difference_sum / double(compared) : kNaN;
}

double MaskAgreement::reference_shadow_share() const {
    return compared > 0 ? double(reference_shadow) / double(compared) : kNaN;
}

}  // namespace ts::bench
