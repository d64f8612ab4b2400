#include "core/light/diffuse_sky_fit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/sh/gauss_legendre.hpp"
#include "core/sh/sh_basis.hpp"
#include "core/util/angles.hpp"

namespace ts::light {
namespace {

constexpr int kNodes = 48;

// The lobe (A_l) of the clamped cosine on bands 0..2.
constexpr double kLobe[3] = {kPi, 2.0 * kPi / 3.0, kPi / 4.0};

// int_-pi^pi cos(m b) max(0, a + c cos b) db, m = 0..2, in closed form (c >= 0).
std::array<double, 3> clamped_cosine_harmonics(double a, double c) {
    double t;  // the half-width of the arc where a + c cos b > 0
    if (a >= c) t = kPi;
    else if (a <= -c) return {0.0, 0.0, 0.0};
    else t = std::acos(-a / c);
    const double s1 = std::sin(t), s2 = std::sin(2 * t), s3 = std::sin(3 * t);
    return {2 * (a * t + c * s1), 2 * a * s1 + c * (t + s2 / 2), a * s2 + c * (s1 + s3 / 3)};
}

// The inverse of a 9 x 9 matrix (here symmetric positive definite) by Gauss-Jordan elimination.
std::array<double, 81> invert(std::array<double, 81> a) {
    std::array<double, 81> inv{};
    for (int i = 0; i < 9; ++i) inv[std::size_t(i * 9 + i)] = 1.0;
    for (int c = 0; c < 9; ++c) {
        int p = c;
        for (int r = c + 1; r < 9; ++r)
            if (std::abs(a[std::size_t(r * 9 + c)]) > std::abs(a[std::size_t(p * 9 + c)])) p = r;
        if (std::abs(a[std::size_t(p * 9 + c)]) < 1e-300) throw std::logic_error("diffuse sky fit: singular");
        for (int k = 0; k < 9; ++k) {
            std::swap(a[std::size_t(c * 9 + k)], a[std::size_t(p * 9 + k)]);
            std::swap(inv[std::size_t(c * 9 + k)], inv[std::size_t(p * 9 + k)]);
        }
        const double d = a[std::size_t(c * 9 + c)];
        for (int k = 0; k < 9; ++k) a[std::size_t(c * 9 + k)] /= d, inv[std::size_t(c * 9 + k)] /= d;
        for (int r = 0; r < 9; ++r) {
            if (r == c) continue;
            const double f = a[std::size_t(r * 9 + c)];
            if (f == 0) continue;
            for (int k = 0; k < 9; ++k)
                a[std::size_t(r * 9 + k)] -= f * a[std::size_t(c * 9 + k)],
                    inv[std::size_t(r * 9 + k)] -= f * inv[std::size_t(c * 9 + k)];
        }
    }
    return inv;
}

}  // namespace

DiffuseSkyFit::DiffuseSkyFit() {
    const double u0 = std::cos(kDiffuseFitMaxSlopeDeg * kPi / 180.0);
    const sh::GaussLegendre gl = sh::gauss_legendre(kNodes, u0, 1.0);
    for (int k = 0; k < kNodes; ++k) {
        u_[std::size_t(k)] = gl.nodes[std::size_t(k)];
        w_[std::size_t(k)] = gl.weights[std::size_t(k)];
        const sh::ShVec r = sh::eval_height_factors(u_[std::size_t(k)]);
        for (int i = 0; i < 9; ++i)
            radial_[std::size_t(k)][std::size_t(i)] = kLobe[sh::band_of(i)] / kPi * r[std::size_t(i)];
    }
    // G: the azimuthal integral of trig_m trig_m' is 2 pi (m = m' = 0), pi (m = m' != 0) or 0.
    std::array<double, 81> g{};
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j) {
            const int m = sh::order_of(i);
            if (sh::order_of(j) != m) continue;
            double s = 0;
            for (int k = 0; k < kNodes; ++k)
                s += w_[std::size_t(k)] * radial_[std::size_t(k)][std::size_t(i)] * radial_[std::size_t(k)][std::size_t(j)];
            g[std::size_t(i * 9 + j)] = s * (m == 0 ? 2.0 * kPi : kPi);
        }
    g_inverse_ = invert(g);
}

std::array<double, 9> DiffuseSkyFit::ring_factors(double z) const {
    const double rz = std::sqrt(std::max(0.0, 1.0 - z * z));
    std::array<double, 9> h{};
    for (int k = 0; k < kNodes; ++k) {
        const double u = u_[std::size_t(k)];
        const std::array<double, 3> c =
            clamped_cosine_harmonics(u * z, std::sqrt(std::max(0.0, 1.0 - u * u)) * rz);
        for (int i = 0; i < 9; ++i)
            h[std::size_t(i)] += w_[std::size_t(k)] * radial_[std::size_t(k)][std::size_t(i)] *
                                 c[std::size_t(std::abs(sh::order_of(i)))];
    }
    std::array<double, 9> f{};
    for (int i = 0; i < 9; ++i) {
        double s = 0;
        for (int j = 0; j < 9; ++j) s += g_inverse_[std::size_t(i * 9 + j)] * h[std::size_t(j)] / kPi;
        f[std::size_t(i)] = s;
    }
    return f;
}

}  // namespace ts::light
