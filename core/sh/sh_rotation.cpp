#include "core/sh/sh_rotation.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <stdexcept>
#include <utility>
#include <vector>

namespace ts::sh {
namespace {

// Inverse of an n x n row-major matrix by Gauss-Jordan elimination with partial pivoting.
std::vector<double> invert(std::vector<double> a, int n) {
    std::vector<double> inv(static_cast<std::size_t>(n * n), 0.0);
    for (int i = 0; i < n; ++i) inv[i * n + i] = 1.0;
    for (int c = 0; c < n; ++c) {
        int piv = c;
        for (int r = c + 1; r < n; ++r)
            if (std::abs(a[r * n + c]) > std::abs(a[piv * n + c])) piv = r;
        if (std::abs(a[piv * n + c]) < 1e-12) throw std::logic_error("ShRotation: singular sample set");
        for (int k = 0; k < n; ++k) {
            std::swap(a[c * n + k], a[piv * n + k]);
            std::swap(inv[c * n + k], inv[piv * n + k]);
        }
        const double d = a[c * n + c];
        for (int k = 0; k < n; ++k) {
            a[c * n + k] /= d;
            inv[c * n + k] /= d;
        }
        for (int r = 0; r < n; ++r) {
            if (r == c) continue;
            const double f = a[r * n + c];
            if (f == 0.0) continue;
            for (int k = 0; k < n; ++k) {
                a[r * n + k] -= f * a[c * n + k];
                inv[r * n + k] -= f * inv[c * n + k];
            }
        }
    }
    return inv;
}

// 7 fixed, well-spread sample directions (generic: no symmetry that would make a band's
// sample matrix singular). Band l uses the first 2l+1.
std::array<glm::dvec3, 7> sample_directions() {
    std::array<glm::dvec3, 7> d{};
    // Points of a golden-angle spiral, slightly jittered in z so no two are antipodal.
    for (int k = 0; k < 7; ++k) {
        const double z = 0.93 - 1.8 * k / 6.0;
        const double phi = 2.399963229728653 * k + 0.3;
        const double r = std::sqrt(1.0 - z * z);
        d[k] = glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
    }
    return d;
}

struct BandInverses {
    std::array<glm::dvec3, 7> dirs;
    std::vector<double> inv[4];  // inv[l]: (2l+1)^2, row-major, inverse of Y_l[m][k]
};

BandInverses make_band_inverses() {
    BandInverses b;
    b.dirs = sample_directions();
    for (int l = 1; l < kBands; ++l) {
        const int n = 2 * l + 1;
        std::vector<double> y(static_cast<std::size_t>(n * n));
        for (int k = 0; k < n; ++k) {
            const ShVec e = eval(b.dirs[k]);
            for (int m = 0; m < n; ++m) y[m * n + k] = e[l * l + m];
        }
        b.inv[l] = invert(y, n);
    }
    return b;
}

const BandInverses& band_inverses() {
    static const BandInverses b = make_band_inverses();  // immutable after first use
    return b;
}

template <std::size_t N>
void band_matrix(const glm::dmat3& R, int l, std::array<double, N>& out) {
    const BandInverses& b = band_inverses();
    const int n = 2 * l + 1;
    std::vector<double> yr(static_cast<std::size_t>(n * n));
    for (int k = 0; k < n; ++k) {
        const ShVec e = eval(R * b.dirs[k]);
        for (int m = 0; m < n; ++m) yr[m * n + k] = e[l * l + m];
    }
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            double s = 0.0;
            for (int k = 0; k < n; ++k) s += yr[i * n + k] * b.inv[l][k * n + j];
            out[i * n + j] = s;
        }
}

}  // namespace

ShRotation::ShRotation(const glm::dmat3& R) {
    band_matrix(R, 1, m1_);
    band_matrix(R, 2, m2_);
    band_matrix(R, 3, m3_);
}

ShRotation ShRotation::to_local_frame(const glm::dmat3& frame) {
    return ShRotation(glm::transpose(frame));
}

// With y_l(R d) = M y_l(d) and M orthogonal, g(w) = f(R^T w) has coefficients M f.
ShVec ShRotation::apply(const ShVec& f) const {
    ShVec g{};
    g[0] = f[0];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) g[1 + i] += m1_[i * 3 + j] * f[1 + j];
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) g[4 + i] += m2_[i * 5 + j] * f[4 + j];
    for (int i = 0; i < 7; ++i)
        for (int j = 0; j < 7; ++j) g[9 + i] += m3_[i * 7 + j] * f[9 + j];
    return g;
}

void ShRotation::apply(const float in[kCount], float out[kCount]) const {
    ShVec f{};
    for (int i = 0; i < kCount; ++i) f[i] = in[i];
    const ShVec g = apply(f);
    for (int i = 0; i < kCount; ++i) out[i] = static_cast<float>(g[i]);
}

}  // namespace ts::sh
