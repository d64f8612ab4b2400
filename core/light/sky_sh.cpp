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
// sum_j w L_j trig_m(phi_j), m = 0..3, and A_lm(z) once (sh::eval_height_factors). Same nodes
// and weights as the direct sum_j w L_j Y(d_j), a quarter of the work besides the radiance itself (equal within rounding, tests/light/sky_sh_test.cpp).
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
    // projection, sh::eval_height_factors) or the diffuse fit's (DiffuseSkyFit::ring_factors).
    void flush(const sh::ShVec& factor, std::array<glm::dvec3, sh::kCount>& acc) const {
        for (int i = 0; i < sh::kCount; ++i) {
            const int m = sh::order_of(i);
            acc[std::size_t(i)] += (m >= 0 ? c[m] : s[-m]) * factor[std::size_t(i)];
        }
    }
};

// Calls on_ring(ring) with each ring's sums of the sky's radiance, in the rule's order.
template <class OnRing>
void for_each_ring(const Sky& sky, const HemisphereRule& rule, OnRing&& on_ring) {
    RingSums ring;
    for_each_sky_node(rule, true, [&](const glm::dvec3& d, double w) {
        if (d.z != ring.z) {
            if (!std::isnan(ring.z)) on_ring(ring);
            ring = RingSums{};
            ring.z = d.z;
        }
        ring.add(d, glm::dvec3(sky.lighting_radiance(d)) * w);
    });
    if (!std::isnan(ring.z)) on_ring(ring);
}

SkySh to_sky_sh(const std::array<glm::dvec3, sh::kCount>& acc) {
    SkySh out{};
    for (int i = 0; i < sh::kCount; ++i) out[i] = Rgb(acc[i]);
    return out;
}

}  // namespace

SkySh project_sky_sh(const Sky& sky, const HemisphereRule& rule) {
    std::array<glm::dvec3, sh::kCount> acc{};
    for_each_ring(sky, rule, [&](const RingSums& ring) { ring.flush(sh::eval_height_factors(ring.z), acc); });
    return to_sky_sh(acc);
}

SkySh project_diffuse_sky_sh(const Sky& sky, const HemisphereRule& rule) {
    return DiffuseSkyProjector().project(sky, rule, nullptr);
}

SkySh DiffuseSkyProjector::project(const Sky& sky, SkySh* radiance) {
    if (const auto* hdr = dynamic_cast<const HdrSky*>(&sky)) {
        if (radiance) *radiance = hdr->cached_sh();
        return hdr->cached_diffuse_sh();
    }
    return project(sky, default_sky_rule(sky), radiance);
}

SkySh DiffuseSkyProjector::project(const Sky& sky, const HemisphereRule& rule, SkySh* radiance) {
    if (rule.n_z != rule_.n_z || rule.n_phi != rule_.n_phi || diffuse_factors_.empty()) {
        // Per ring (the rings' heights do not depend on the azimuths): the projection's factors,
        // and the diffuse fit's for bands 0..2.
        const DiffuseSkyFit fit;
        radiance_factors_.clear();
        diffuse_factors_.clear();
        double last = std::numeric_limits<double>::quiet_NaN();
        for_each_sky_node({rule.n_z, 1}, true, [&](const glm::dvec3& d, double) {
            if (d.z == last) return;
            last = d.z;
            radiance_factors_.push_back(sh::eval_height_factors(d.z));
            sh::ShVec f = radiance_factors_.back();
            const std::array<double, 9> fitted = fit.ring_factors(d.z);
            std::copy(fitted.begin(), fitted.end(), f.begin());
            diffuse_factors_.push_back(f);
        });
        rule_ = rule;
    }
    std::array<glm::dvec3, sh::kCount> diffuse{}, projected{};
    std::size_t k = 0;
    for_each_ring(sky, rule, [&](const RingSums& ring) {
        ring.flush(diffuse_factors_.at(k), diffuse);
        if (radiance) ring.flush(radiance_factors_.at(k), projected);
        ++k;
    });
    if (radiance) *radiance = to_sky_sh(projected);
    return to_sky_sh(diffuse);
}

SkySh project_diffuse_sky_sh(const Sky& sky) {
    return DiffuseSkyProjector().project(sky);
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
