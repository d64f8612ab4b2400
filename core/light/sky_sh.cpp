#include "core/light/sky_sh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/light/diffuse_sky_fit.hpp"
#include "core/light/hdr_sky.hpp"
#include "core/sh/sh_basis.hpp"
#include "core/util/angles.hpp"

namespace ts::light {

HemisphereRule default_sky_rule(const Sky& sky) {
    HemisphereRule rule{32, 128};
    if (const auto* hdr = dynamic_cast<const HdrSky*>(&sky)) {
        rule.n_phi = std::max(rule.n_phi, hdr->width());
        rule.n_z = std::max(rule.n_z, (hdr->height() + 1) / 2);
    }
    return rule;
}

namespace {

// The quadrature's nodes come in rings of equal z (and weight), and every real SH basis
// function factors as Y_lm(d) = A_lm(z) trig_m(phi), trig = cos(m phi) for m >= 0 and
// sin(|m| phi) for m < 0 (sh_shared.h's ts_sh_eval). So each ring needs only the Fourier sums
// sum_j w L_j trig_m(phi_j), m = 0..3, and A_lm(z) once: sh::eval at the four azimuths where
// trig_m = 1. Same nodes and weights as the direct sum_j w L_j Y(d_j), a quarter of the work
// besides the radiance itself (equal within rounding, tests/light/sky_sh_test.cpp).
struct RingSums {
    double z = std::numeric_limits<double>::quiet_NaN();
    glm::dvec3 c[4] = {}, s[4] = {};  // sum w L cos(m phi), sum w L sin(m phi); s[0] unused
    void add(const glm::dvec3& d, const glm::dvec3& wl) {
        const double r = std::sqrt(d.x * d.x + d.y * d.y);
        const double cp = r > 0 ? d.x / r : 1.0, sp = r > 0 ? d.y / r : 0.0;
        const double c2 = cp * cp - sp * sp, s2 = 2 * cp * sp;
        const double c3 = cp * c2 - sp * s2, s3 = sp * c2 + cp * s2;
        c[0] += wl, c[1] += wl * cp, s[1] += wl * sp, c[2] += wl * c2, s[2] += wl * s2, c[3] += wl * c3,
            s[3] += wl * s3;
    }
    // acc_i += ring sum of trig_m(i) times factor_i: Y_i's factor at the ring's z (the
    // projection) or the diffuse fit's (DiffuseSkyFit::ring_factors).
    void flush(const std::array<double, sh::kCount>& factor, std::array<glm::dvec3, sh::kCount>& acc) const {
        for (int i = 0; i < sh::kCount; ++i) {
            const int m = sh::order_of(i);
            acc[std::size_t(i)] += (m >= 0 ? c[m] : s[-m]) * factor[std::size_t(i)];
        }
    }
};

// Y_i's factor at height z: sh::eval at the azimuths where trig_m = 1 (m >= 0: 0; m < 0: pi / (2|m|)).
std::array<double, sh::kCount> projection_factors(double z) {
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    sh::ShVec a[4];
    a[0] = sh::eval({r, 0.0, z});
    for (int k = 1; k <= 3; ++k) {
        const double phi = kPi / (2.0 * k);
        a[k] = sh::eval({r * std::cos(phi), r * std::sin(phi), z});
    }
    std::array<double, sh::kCount> f{};
    for (int i = 0; i < sh::kCount; ++i) {
        const int m = sh::order_of(i);
        f[std::size_t(i)] = m >= 0 ? a[0][std::size_t(i)] : a[-m][std::size_t(i)];
    }
    return f;
}

// The ring sums of the sky's radiance, each ring weighted by factors(z).
template <class Factors>
SkySh ring_projection(const Sky& sky, const HemisphereRule& rule, Factors&& factors) {
    std::array<glm::dvec3, sh::kCount> acc{};
    RingSums ring;
    const auto flush = [&] {
        if (!std::isnan(ring.z)) ring.flush(factors(ring.z), acc);
    };
    for_each_sky_node(rule, true, [&](const glm::dvec3& d, double w) {
        if (d.z != ring.z) {
            flush();
            ring = RingSums{};
            ring.z = d.z;
        }
        ring.add(d, glm::dvec3(sky.radiance(d)) * w);
    });
    flush();
    SkySh out{};
    for (int i = 0; i < sh::kCount; ++i) out[i] = Rgb(acc[i]);
    return out;
}

}  // namespace

SkySh project_sky_sh(const Sky& sky, const HemisphereRule& rule) {
    return ring_projection(sky, rule, projection_factors);
}

namespace {

// Per ring of the rule (in for_each_sky_node's order), the diffuse fit's factors for bands 0..2
// and the projection's for band 3.
std::vector<std::array<double, sh::kCount>> diffuse_ring_factors(const HemisphereRule& rule) {
    const DiffuseSkyFit fit;
    std::vector<std::array<double, sh::kCount>> out;
    double last = std::numeric_limits<double>::quiet_NaN();
    for_each_sky_node({rule.n_z, 1}, true, [&](const glm::dvec3& d, double) {
        if (d.z == last) return;
        last = d.z;
        std::array<double, sh::kCount> f = projection_factors(d.z);
        const std::array<double, 9> fitted = fit.ring_factors(d.z);
        std::copy(fitted.begin(), fitted.end(), f.begin());
        out.push_back(f);
    });
    return out;
}

SkySh project_with_factors(const Sky& sky, const HemisphereRule& rule,
                           const std::vector<std::array<double, sh::kCount>>& factors) {
    std::size_t k = 0;
    return ring_projection(sky, rule, [&](double) { return factors.at(k++); });
}

}  // namespace

SkySh project_diffuse_sky_sh(const Sky& sky, const HemisphereRule& rule) {
    return project_with_factors(sky, rule, diffuse_ring_factors(rule));
}

SkySh DiffuseSkyProjector::project(const Sky& sky) {
    if (const auto* hdr = dynamic_cast<const HdrSky*>(&sky)) return hdr->cached_diffuse_sh();
    const HemisphereRule rule = default_sky_rule(sky);
    if (rule.n_z != rule_.n_z || rule.n_phi != rule_.n_phi || factors_.empty()) {
        factors_ = diffuse_ring_factors(rule);
        rule_ = rule;
    }
    return project_with_factors(sky, rule, factors_);
}

SkySh project_diffuse_sky_sh(const Sky& sky) {
    if (const auto* hdr = dynamic_cast<const HdrSky*>(&sky)) return hdr->cached_diffuse_sh();
    return project_diffuse_sky_sh(sky, default_sky_rule(sky));
}

SkySh project_sky_sh(const Sky& sky) {
    // An HDR map does not change with the sun: project it once (its rule can be large).
    if (const auto* hdr = dynamic_cast<const HdrSky*>(&sky)) return hdr->cached_sh();
    return project_sky_sh(sky, default_sky_rule(sky));
}

Rgb reconstruct_sky_sh(const SkySh& coefficients, const glm::dvec3& dir) {
    const sh::ShVec y = sh::eval(dir);
    glm::dvec3 v(0.0);
    for (int i = 0; i < sh::kCount; ++i) v += glm::dvec3(coefficients[i]) * y[i];
    return Rgb(v);
}

}  // namespace ts::light
