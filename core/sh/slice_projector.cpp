#include "core/sh/slice_projector.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/sh/gauss_legendre.hpp"
#include "core/sh/sh_basis.hpp"
#include "core/sh/sh_shared.hpp"

namespace ts::sh {
namespace {

// K_l|m| P_l^|m|(cos theta): the polar part of y_lm, read off the shared basis at phi = 0
// (y_l,+|m| = sqrt2 K P cos(0)).
std::array<double, 10> polar_parts(double theta) {
    const ShVec y = eval(glm::dvec3(std::sin(theta), 0.0, std::cos(theta)));
    std::array<double, 10> p{};
    for (int l = 0; l < kBands; ++l)
        for (int am = 0; am <= l; ++am) {
            const double v = y[index(l, am)];
            p[l * (l + 1) / 2 + am] = am == 0 ? v : v / std::sqrt(2.0);
        }
    return p;
}

// A[l'][p] = int_{-1}^{1} Phat_l'(x) K_l|m| P_l^|m|(x) dx, by Gauss-Legendre in theta (the
// integrand is smooth in theta; 64 nodes are exact to round-off for these degrees).
std::array<std::array<double, 10>, 4> legendre_to_polar() {
    std::array<std::array<double, 10>, 4> a{};
    const GaussLegendre gl = gauss_legendre(64, 0.0, kPi);
    for (std::size_t q = 0; q < gl.nodes.size(); ++q) {
        const double t = gl.nodes[q];
        const double w = gl.weights[q] * std::sin(t);
        const std::array<double, 4> ph = normalized_legendre(std::cos(t));
        const std::array<double, 10> pp = polar_parts(t);
        for (int lp = 0; lp < 4; ++lp)
            for (int p = 0; p < 10; ++p) a[lp][p] += w * ph[lp] * pp[p];
    }
    return a;
}

}  // namespace

std::array<double, 4> normalized_legendre(double x) {
    return {std::sqrt(0.5), std::sqrt(1.5) * x, std::sqrt(2.5) * 0.5 * (3.0 * x * x - 1.0),
            std::sqrt(3.5) * 0.5 * (5.0 * x * x * x - 3.0 * x)};
}

double SliceProjector::azimuth(int k, int slices) {
    return 2.0 * kPi * k / slices;
}

SliceProjector::SliceProjector(int slices) : slices_(slices) {
    if (slices < 4)
        throw std::invalid_argument("SliceProjector: need at least 4 slices, got " + std::to_string(slices));
    const double delta = 2.0 * kPi / slices;
    azimuth_weight_.resize(static_cast<std::size_t>(slices) * kCount);
    for (int k = 0; k < slices; ++k)
        for (int i = 0; i < kCount; ++i)
            azimuth_weight_[k * kCount + i] =
                static_cast<float>(shared::ts_slice_azimuth_weight(order_of(i), azimuth(k, slices), delta));

    const auto a = legendre_to_polar();
    matrix_.assign(static_cast<std::size_t>(kCount) * 4 * slices, 0.0f);
    for (int i = 0; i < kCount; ++i) {
        const int l = band_of(i);
        const int am = std::abs(order_of(i));
        const int p = l * (l + 1) / 2 + am;
        for (int k = 0; k < slices; ++k) {
            const double w = shared::ts_slice_azimuth_weight(order_of(i), azimuth(k, slices), delta);
            for (int lp = 0; lp < 4; ++lp)
                matrix_[static_cast<std::size_t>(i) * 4 * slices + 4 * k + lp] = static_cast<float>(w * a[lp][p]);
        }
    }
}

void SliceProjector::project(const float* c, float* out) const {
    const int n = 4 * slices_;
    for (int i = 0; i < kCount; ++i) {
        const float* row = &matrix_[static_cast<std::size_t>(i) * n];
        float s = 0.0f;
        for (int j = 0; j < n; ++j) s += row[j] * c[j];
        out[i] = s;
    }
}

std::array<float, 16> SliceProjector::project(const float* c) const {
    std::array<float, 16> f{};
    project(c, f.data());
    return f;
}

void SliceProjector::project_horizons(const float* sigma, float log_eps, float* out) const {
    for (int i = 0; i < kCount; ++i) out[i] = 0.0f;
    for (int k = 0; k < slices_; ++k) {
        double e[10];
        shared::ts_slice_sh_integrals(sigma[k], log_eps, e);
        const float* w = &azimuth_weight_[static_cast<std::size_t>(k) * kCount];
        out[0] += w[0] * static_cast<float>(e[0]);
        out[1] += w[1] * static_cast<float>(e[2]);
        out[2] += w[2] * static_cast<float>(e[1]);
        out[3] += w[3] * static_cast<float>(e[2]);
        out[4] += w[4] * static_cast<float>(e[5]);
        out[5] += w[5] * static_cast<float>(e[4]);
        out[6] += w[6] * static_cast<float>(e[3]);
        out[7] += w[7] * static_cast<float>(e[4]);
        out[8] += w[8] * static_cast<float>(e[5]);
        out[9] += w[9] * static_cast<float>(e[9]);
        out[10] += w[10] * static_cast<float>(e[8]);
        out[11] += w[11] * static_cast<float>(e[7]);
        out[12] += w[12] * static_cast<float>(e[6]);
        out[13] += w[13] * static_cast<float>(e[7]);
        out[14] += w[14] * static_cast<float>(e[8]);
        out[15] += w[15] * static_cast<float>(e[9]);
    }
}

std::array<float, 16> SliceProjector::project_horizons(const float* sigma, float log_eps) const {
    std::array<float, 16> f{};
    project_horizons(sigma, log_eps, f.data());
    return f;
}

}  // namespace ts::sh
