#include "core/material/log_brdf.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/sh/gauss_legendre.hpp"

namespace ts::sh {
namespace {

// Legendre polynomials P_0..P_3.
std::array<double, 4> legendre(double x) {
    return {1.0, x, 0.5 * (3.0 * x * x - 1.0), 0.5 * (5.0 * x * x * x - 3.0 * x)};
}

// int_a^b P_l(x) dx in closed form (antiderivatives of P_0..P_3).
std::array<double, 4> legendre_integral(double a, double b) {
    auto F = [](double x) {
        return std::array<double, 4>{x, 0.5 * x * x, 0.5 * (x * x * x - x), 0.5 * (1.25 * x * x * x * x - 1.5 * x * x)};
    };
    const auto fa = F(a), fb = F(b);
    return {fb[0] - fa[0], fb[1] - fa[1], fb[2] - fa[2], fb[3] - fa[3]};
}

}  // namespace

ZhVec log_phong_zh(double alpha, double log_eps) {
    if (!(alpha > 0.0) || !(log_eps < 0.0)) throw std::invalid_argument("log_phong_zh: need alpha > 0 and log_eps < 0");
    // zh_l = 2 pi K_l0 int_{-1}^{1} f_log(x) P_l(x) dx with K_l0 = sqrt((2l+1)/(4 pi)).
    // f_log = log N + g(x), g = log eps for x < x* = eps^(1/alpha), alpha log x above.
    const double x_star = std::exp(log_eps / alpha);
    std::array<double, 4> integral{};
    const auto below = legendre_integral(-1.0, x_star);
    for (int l = 0; l < 4; ++l) integral[l] = log_eps * below[l];
    // Above x*: substitute x = e^u (u in [log x*, 0]) so the integrand alpha u P_l(e^u) e^u is
    // smooth even when x* is tiny.
    const GaussLegendre gl = gauss_legendre(48, std::log(x_star), 0.0);
    for (std::size_t q = 0; q < gl.nodes.size(); ++q) {
        const double u = gl.nodes[q];
        const double x = std::exp(u);
        const auto p = legendre(x);
        for (int l = 0; l < 4; ++l) integral[l] += gl.weights[q] * alpha * u * p[l] * x;
    }
    const double log_norm = std::log((alpha + 1.0) / (2.0 * kPi));
    ZhVec zh{};
    for (int l = 0; l < 4; ++l) zh[l] = 2.0 * kPi * std::sqrt((2.0 * l + 1.0) / (4.0 * kPi)) * integral[l];
    zh[0] += log_norm * kSqrt4Pi;
    return zh;
}

LogBrdfTable::LogBrdfTable(double log_eps, int entries) : log_eps_(log_eps) {
    if (entries < 2) throw std::invalid_argument("LogBrdfTable: need >= 2 entries");
    rows_.reserve(entries);
    for (int j = 0; j < entries; ++j) {
        const double alpha = std::pow(kMaxAlpha, static_cast<double>(j) / (entries - 1));
        rows_.push_back(log_phong_zh(alpha, log_eps));
    }
}

ZhVec LogBrdfTable::phong(double alpha) const {
    const double a = std::clamp(alpha, kMinAlpha, kMaxAlpha);
    const double x = std::log(a) / std::log(kMaxAlpha) * (rows_.size() - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(x), rows_.size() - 2);
    const double t = x - static_cast<double>(i);
    ZhVec zh{};
    for (int l = 0; l < 4; ++l) zh[l] = (1.0 - t) * rows_[i][l] + t * rows_[i + 1][l];
    return zh;
}

}  // namespace ts::sh
