#include "core/sh/exact_exp.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ts::sh {

ExactExp::ExactExp(int n_z, int n_phi) : quad_(n_z, n_phi) {}

ShVec ExactExp::operator()(const ShVec& f_log) const {
    std::vector<double> v = quad_.reconstruct_values(f_log);
    const double peak = *std::max_element(v.begin(), v.end());
    for (double& x : v) x = std::exp(x - peak);
    const double scale = std::exp(std::min(peak, 700.0));
    return scale * quad_.project_values(v);
}

ExactExp::Range ExactExp::range(const ShVec& f) const {
    const std::vector<double> v = quad_.reconstruct_values(f);
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return {*lo, *hi};
}

}  // namespace ts::sh
