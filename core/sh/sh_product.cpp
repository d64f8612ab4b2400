#include "core/sh/sh_product.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/sh/sphere_quadrature.hpp"

namespace ts::sh {
namespace {

using Dense = std::array<double, kCount * kCount * kCount>;

Dense make_dense() {
    const SphereQuadrature q(8, 16);
    Dense g{};
    for (std::size_t p = 0; p < q.size(); ++p) {
        const double w = q.weights()[p];
        const double* y = q.basis(p);
        for (int i = 0; i < kCount; ++i)
            for (int j = 0; j < kCount; ++j)
                for (int k = 0; k < kCount; ++k) g[(i * kCount + j) * kCount + k] += w * y[i] * y[j] * y[k];
    }
    for (double& v : g)
        if (std::abs(v) < 1e-12) v = 0.0;  // quadrature round-off on exact zeros
    return g;
}

const Dense& dense() {
    static const Dense g = make_dense();
    return g;
}

std::vector<TripleEntry> make_sparse() {
    const Dense& g = dense();
    std::vector<TripleEntry> e;
    for (int k = 0; k < kCount; ++k)
        for (int i = 0; i < kCount; ++i)
            for (int j = i; j < kCount; ++j) {
                const double v = g[(i * kCount + j) * kCount + k];
                if (v != 0.0)
                    e.push_back({static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(j),
                                 static_cast<std::uint8_t>(k), static_cast<float>(v)});
            }
    return e;
}

}  // namespace

const std::vector<TripleEntry>& tripling_tensor() {
    static const std::vector<TripleEntry> e = make_sparse();
    return e;
}

double tripling(int i, int j, int k) {
    return dense()[(i * kCount + j) * kCount + k];
}

namespace {

// The non-zeros regrouped for the hot loops: for each output k a contiguous run of (i, j, g)
// accumulated in registers (no store-to-load chains through out[]).
struct GroupedTensor {
    std::array<int, kCount + 1> start{};
    std::vector<int> i, j;
    std::vector<float> g;
};

GroupedTensor make_grouped() {
    GroupedTensor t;
    const auto& e = tripling_tensor();
    int k = 0;
    for (std::size_t n = 0; n < e.size(); ++n) {
        while (k <= e[n].k) t.start[k++] = static_cast<int>(n);
        t.i.push_back(e[n].i);
        t.j.push_back(e[n].j);
        t.g.push_back(e[n].value);
    }
    while (k <= kCount) t.start[k++] = static_cast<int>(e.size());
    return t;
}

const GroupedTensor& grouped() {
    static const GroupedTensor t = make_grouped();
    return t;
}

}  // namespace

void product(const float* a, const float* b, float* out) {
    const GroupedTensor& t = grouped();
    for (int k = 0; k < kCount; ++k) {
        float s0 = 0.0f, s1 = 0.0f;
        for (int n = t.start[k]; n < t.start[k + 1]; ++n) {
            const int i = t.i[n], j = t.j[n];
            s0 += t.g[n] * a[i] * b[j];
            if (i != j) s1 += t.g[n] * a[j] * b[i];
        }
        out[k] = s0 + s1;
    }
}

void square(const float* a, float* out) {
    const GroupedTensor& t = grouped();
    for (int k = 0; k < kCount; ++k) {
        float s0 = 0.0f, s1 = 0.0f;
        for (int n = t.start[k]; n < t.start[k + 1]; ++n) {
            const int i = t.i[n], j = t.j[n];
            if (i == j)
                s0 += t.g[n] * a[i] * a[i];
            else
                s1 += t.g[n] * a[i] * a[j];
        }
        out[k] = s0 + 2.0f * s1;
    }
}

ShVec product(const ShVec& a, const ShVec& b) {
    ShVec c{};
    const Dense& g = dense();
    for (int i = 0; i < kCount; ++i)
        for (int j = 0; j < kCount; ++j) {
            const double ab = a[i] * b[j];
            if (ab == 0.0) continue;
            for (int k = 0; k < kCount; ++k) c[k] += g[(i * kCount + j) * kCount + k] * ab;
        }
    return c;
}

}  // namespace ts::sh
