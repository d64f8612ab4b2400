#include "app/bench/insolation_agreement.hpp"

#include <algorithm>
#include <cmath>

#include "app/bench/error_stats.hpp"

namespace ts::app {

AgreementRow agreement(const std::string& rsun, const std::string& texels, const std::vector<float>& beam_other,
                       const std::vector<float>& beam_ts, const std::vector<float>& hours_other,
                       const std::vector<float>& hours_ts, const std::vector<std::uint8_t>& in_class) {
    AgreementRow a;
    a.rsun = rsun;
    a.texels = texels;
    std::vector<double> rel, dh;
    for (std::size_t i = 0; i < beam_ts.size(); ++i) {
        if (!in_class[i] || !std::isfinite(beam_other[i]) || !(beam_ts[i] > 0)) continue;
        rel.push_back(double(beam_other[i]) / beam_ts[i] - 1);
        if (std::isfinite(hours_other[i]) && std::isfinite(hours_ts[i])) dh.push_back(double(hours_other[i]) - hours_ts[i]);
    }
    a.n = rel.size();
    if (rel.empty()) return a;
    a.mean = bench::mean(rel);
    a.hours_diff = bench::mean(dh);
    a.within_2pct = double(std::count_if(rel.begin(), rel.end(), [](double r) { return std::abs(r) <= 0.02; })) /
                    double(rel.size());
    a.p5 = bench::percentile(rel, 0.05);
    a.p50 = bench::percentile(rel, 0.5);
    a.p95 = bench::percentile(rel, 0.95);
    return a;
}

}  // namespace ts::app
