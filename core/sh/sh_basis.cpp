#include "core/sh/sh_basis.hpp"

#include <algorithm>
#include <cmath>

#include "core/sh/sh_shared.hpp"

namespace ts::sh {

ShVec eval(const glm::dvec3& d) {
    ShVec y{};
    double raw[kCount];
    shared::ts_sh_eval(d, raw);
    for (int i = 0; i < kCount; ++i) y[i] = raw[i];
    return y;
}

ShVec eval_height_factors(double z) {
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    ShVec at[4];  // at[k]: the basis where trig_m = 1 for m >= 0 (azimuth 0) and for m = -k
    at[0] = eval({r, 0.0, z});
    for (int k = 1; k < kBands; ++k) {
        const double phi = kPi / (2.0 * k);
        at[k] = eval({r * std::cos(phi), r * std::sin(phi), z});
    }
    ShVec h{};
    for (int i = 0; i < kCount; ++i) {
        const int m = order_of(i);
        h[std::size_t(i)] = at[m >= 0 ? 0 : -m][std::size_t(i)];
    }
    return h;
}

double reconstruct(const ShVec& f, const glm::dvec3& d) {
    return dot(f, eval(d));
}

ShVec zh_rotate(const ZhVec& zh, const glm::dvec3& d) {
    double in[kBands] = {zh[0], zh[1], zh[2], zh[3]};
    double out[kCount];
    shared::ts_zh_rotate(in, d, out);
    ShVec f{};
    for (int i = 0; i < kCount; ++i) f[i] = out[i];
    return f;
}

double dot(const ShVec& a, const ShVec& b) {
    double s = 0.0;
    for (int i = 0; i < kCount; ++i) s += a[i] * b[i];
    return s;
}

double non_dc_norm(const ShVec& f) {
    double s = 0.0;
    for (int i = 1; i < kCount; ++i) s += f[i] * f[i];
    return std::sqrt(s);
}

double norm(const ShVec& a) {
    return std::sqrt(dot(a, a));
}

ShVec operator+(const ShVec& a, const ShVec& b) {
    ShVec r{};
    for (int i = 0; i < kCount; ++i) r[i] = a[i] + b[i];
    return r;
}
ShVec operator-(const ShVec& a, const ShVec& b) {
    ShVec r{};
    for (int i = 0; i < kCount; ++i) r[i] = a[i] - b[i];
    return r;
}
ShVec operator*(double s, const ShVec& a) {
    ShVec r{};
    for (int i = 0; i < kCount; ++i) r[i] = s * a[i];
    return r;
}

}  // namespace ts::sh
