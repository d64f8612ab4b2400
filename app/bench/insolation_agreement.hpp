#pragma once
// How closely another model's daily beam irradiation follows terrashade's, texel by texel, over
// one class of texels (open terrain, the rest): `bench insolation` compares r.sun with it.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace ts::app {

// The relative difference d = other / terrashade - 1 over the texels of a class.
struct AgreementRow {
    std::string rsun, texels;  // the other model's variant, the class of texels
    std::size_t n = 0;
    double mean = std::numeric_limits<double>::quiet_NaN(), p5 = mean, p50 = mean, p95 = mean;
    double within_2pct = mean;  // share of the texels with |d| <= 2%
    double hours_diff = mean;   // mean other hours of sun - terrashade hours of direct sun, h
};

// Over the texels i with in_class[i], a finite beam_other[i] and beam_ts[i] > 0 (a texel with no
// terrashade beam has no relative difference).
AgreementRow agreement(const std::string& rsun, const std::string& texels, const std::vector<float>& beam_other,
                       const std::vector<float>& beam_ts, const std::vector<float>& hours_other,
                       const std::vector<float>& hours_ts, const std::vector<std::uint8_t>& in_class);

}  // namespace ts::app
