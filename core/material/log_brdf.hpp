#pragma once
// Log-BRDF ZH tables [slides "Log-BRDF SH Coefficients"]: the cosine-weighted lobe
//   f(theta) = (alpha + 1)/(2 pi) cos^alpha(theta)  (alpha = 1: the diffuse clamped cosine, cos/pi)
// has log f = -inf on the lower hemisphere and at the horizon; it is clamped at a floor
// epsilon relative to the lobe's peak:
//   f_log(theta) = log((alpha+1)/(2 pi)) + max(alpha log cos theta, log eps)  (upper hemisphere)
//                = log((alpha+1)/(2 pi)) + log eps                          (lower hemisphere)
// The slides floor the lower hemisphere at log eps without the normalisation, which makes a
// jump at the horizon (up to log 160 for alpha = 1000) and more ringing; the relative floor is
// continuous. ZH coefficients are integrated in closed form where possible and by
// Gauss-Legendre elsewhere (exact to ~1e-12); the table holds exponents 1..1000 and is
// interpolated linearly in log alpha. Rotate with zh_rotate to the normal (diffuse) or the
// mirror direction (Phong).
// (Namespace ts::sh until the renderer's files say material::, docs/architecture.md.)
#include <vector>

#include "core/sh/sh_basis.hpp"

namespace ts::sh {

// log(0.05): the smallest RMS error of the exponentiated diffuse lobe against the projected
// clamped cosine, albedo within 2% (docs/charts/sh_log_epsilon.png). Glossy lobes (alpha >~ 20)
// want a smaller epsilon: pass it explicitly.
inline constexpr double kDefaultBrdfLogEps = -2.995732273553991;

// Exact log-ZH coefficients of the clamped lobe (no table).
ZhVec log_phong_zh(double alpha, double log_eps);

class LogBrdfTable {
public:
    explicit LogBrdfTable(double log_eps = kDefaultBrdfLogEps, int entries = 64);

    double log_eps() const { return log_eps_; }
    // Phong exponent alpha in [1, 1000] (clamped), interpolated in log alpha.
    ZhVec phong(double alpha) const;
    ZhVec diffuse() const { return rows_.front(); }

    static constexpr double kMinAlpha = 1.0;
    static constexpr double kMaxAlpha = 1000.0;

private:
    double log_eps_;
    std::vector<ZhVec> rows_;  // rows_[j] at alpha = 1000^(j / (entries - 1))
};

}  // namespace ts::sh
