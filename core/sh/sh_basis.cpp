#include "core/sh/sh_basis.hpp"

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
