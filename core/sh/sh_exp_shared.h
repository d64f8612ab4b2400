// The single definition of the hybrid SH exponentiation (DC isolation, optimal linear, scaling
// and squaring; Ren et al. 2006), shared by C++ (core/render/transfer.cpp) and GLSL
// (gpu/shaders/render_transfer.comp), in the style of core/sh/sh_shared.h.
//
// Unlike sh_shared.h this file computes in float in both languages: the GPU has nothing else,
// and the CPU running the same float operations in the same order makes the two agree to
// rounding (a double CPU path would differ from the GPU by the float error of up to 24 SH
// squarings). It follows core/sh/sh_exp.cpp's exp_hybrid step for step (same table, same
// normalised squarings, same clamp), except that the number of squarings is found by exact
// halving instead of ceil(log2(.)) (the same k, decided identically on both sides).
//
// Common subset of C++20 and GLSL 4.50: the macros of glsl_compat.h, float literals with an
// f suffix (both languages accept it), for/while/if, sqrt/log/exp/min/isnan/isinf.
// C++ side: include core/sh/sh_exp_shared.hpp (namespace ts::sh::exp_shared).
// GLSL side: `#define TS_GLSL 1` then `#include "core/sh/sh_exp_shared.h"`.
#ifndef TS_SH_EXP_SHARED_H
#define TS_SH_EXP_SHARED_H

#include "core/util/glsl_compat.h"
#include "core/sh/sh_product_shared.h"

// A quiet NaN (a void texel's transfer vector).
#ifdef TS_GLSL
#define TS_QUIET_NAN_F uintBitsToFloat(0x7fc00000u)
#else
#define TS_QUIET_NAN_F __builtin_nanf("")
#endif
// sqrt(4 pi): the DC coefficient of the constant function 1.
#define TS_SQRT_4PI_F 3.5449077f
// exp(80) ~ 5.5e34 < FLT_MAX: the final scale is clamped there, never Inf.
#define TS_EXP_MAX_LOG_SCALE 80.0f

// The optimal-linear table a(m), b(m) fitted by core/sh/optimal_linear_fit.cpp (rows
// {magnitude, a, b} at equal magnitude steps, first row at 0).
struct TsLinearRow {
    float magnitude;
    float a;
    float b;
};
#define TS_LINEAR_ROWS 129
const TsLinearRow kTsLinearTable[TS_LINEAR_ROWS] = {
#include "core/sh/optimal_linear_table.inc"
};

// Where the rows are read. C++ reads the array above. A shader #defines these three before
// including this file to read a storage buffer the host filled from the same array
// (gpu/render uploads exp_shared::kTsLinearTable): llvmpipe copies a dynamically indexed
// constant array into every invocation, which slows the whole exponentiation several times.
#ifndef TS_LINEAR_M
#define TS_LINEAR_M(i) kTsLinearTable[i].magnitude
#define TS_LINEAR_A(i) kTsLinearTable[i].a
#define TS_LINEAR_B(i) kTsLinearTable[i].b
#endif

// a(m) and b(m) by linear interpolation in the table, clamped beyond its last row
// (sh::optimal_linear_coeffs).
TS_INLINE void ts_optimal_linear_coeffs(float magnitude, TS_OUT_ARRAY(float, ab, 2)) {
    float step = TS_LINEAR_M(1) - TS_LINEAR_M(0);
    float x = (magnitude > 0.0f ? magnitude : 0.0f) / step;
    if (!(x < float(TS_LINEAR_ROWS - 1))) {
        ab[0] = TS_LINEAR_A(TS_LINEAR_ROWS - 1);
        ab[1] = TS_LINEAR_B(TS_LINEAR_ROWS - 1);
        return;
    }
    int i = int(x);
    float t = x - float(i);
    ab[0] = TS_LINEAR_A(i) + t * (TS_LINEAR_A(i + 1) - TS_LINEAR_A(i));
    ab[1] = TS_LINEAR_B(i) + t * (TS_LINEAR_B(i + 1) - TS_LINEAR_B(i));
}

TS_INLINE bool ts_sh_all_finite(TS_IN_ARRAY(float, v, 16)) {
    bool finite = true;
    for (int i = 0; i < 16; ++i)
        if (isnan(v[i]) || isinf(v[i])) finite = false;
    return finite;
}

TS_INLINE float ts_sh_norm(TS_IN_ARRAY(float, v, 16)) {
    float s = 0.0f;
    for (int i = 0; i < 16; ++i) s += v[i] * v[i];
    return sqrt(s);
}

// The scaling step of both squaring methods: the fewest halvings k of m that bring it to at most
// `threshold` (at most max_squarings); scale[0] = 2^-k. Halving is exact in float, so C++ and
// GLSL find the same k for the same m.
TS_INLINE int ts_sh_halvings(float m, float threshold, int max_squarings, TS_OUT_ARRAY(float, scale, 1)) {
    int k = 0;
    scale[0] = 1.0f;
    while (m * scale[0] > threshold && k < max_squarings) {
        scale[0] *= 0.5f;
        ++k;
    }
    return k;
}

// The squaring step of both methods: g <- g^(2^k) by k SH squarings, each renormalised, with the
// log of the dropped norms in log_scale[0] (so no intermediate overflows). False when a norm is
// zero or infinite (the caller then gives zeros).
TS_INLINE bool ts_sh_square_k_times(TS_INOUT_ARRAY(float, g, 16), int k, TS_OUT_ARRAY(float, log_scale, 1)) {
    log_scale[0] = 0.0f;
    for (int s = 0; s < k; ++s) {
        float h[16];
        ts_sh_square(g, h);
        float n = ts_sh_norm(h);
        if (!(n > 0.0f) || isinf(n)) return false;
        float inv = 1.0f / n;
        for (int i = 0; i < 16; ++i) g[i] = h[i] * inv;
        log_scale[0] = 2.0f * log_scale[0] + log(n);
    }
    return true;
}

// exp of the log-SH vector f (16 coefficients) by the hybrid method:
//  - DC isolation: exp(f) = exp(f_0 / sqrt(4 pi)) * exp(f_hat), f_hat = f without its DC;
//  - scaling: k = the fewest halvings that bring m = |f_hat| to at most `threshold` (at most
//    max_squarings);
//  - optimal linear: exp(f_hat / 2^k) ~ a(m') 1 + b(m') f_hat / 2^k, m' = m / 2^k;
//  - squaring: k SH squarings, each renormalised with its log-norm kept apart, so no
//    intermediate overflows; the scalars are applied once at the end, clamped at exp(80).
// Non-finite input, or a result that is not finite, gives zeros (as sh::sh_exp).
TS_INLINE void ts_sh_exp_hybrid(TS_IN_ARRAY(float, f, 16), float threshold, int max_squarings,
                                TS_OUT_ARRAY(float, result, 16)) {
    for (int i = 0; i < 16; ++i) result[i] = 0.0f;
    if (!ts_sh_all_finite(f)) return;
    float m2 = 0.0f;
    for (int i = 1; i < 16; ++i) m2 += f[i] * f[i];
    float m = sqrt(m2);
    float scale[1];
    int k = ts_sh_halvings(m, threshold, max_squarings, scale);
    float ab[2];
    ts_optimal_linear_coeffs(m * scale[0], ab);
    float g[16];
    g[0] = ab[0] * TS_SQRT_4PI_F;
    for (int i = 1; i < 16; ++i) g[i] = ab[1] * f[i] * scale[0];
    float log_scale[1];
    if (!ts_sh_square_k_times(g, k, log_scale)) return;  // zeros
    float e = exp(min(log_scale[0] + f[0] / TS_SQRT_4PI_F, TS_EXP_MAX_LOG_SCALE));
    for (int i = 0; i < 16; ++i) result[i] = e * g[i];
    if (!ts_sh_all_finite(result))
        for (int i = 0; i < 16; ++i) result[i] = 0.0f;
}

// The exponent of a texel's transfer vector, f = V_log + F_log. False for a void texel (any NaN
// in V_log or F_log), whose T is then NaN in every coefficient (set here); true otherwise (t is
// left to the exponentiation).
TS_INLINE bool ts_transfer_exponent(TS_IN_ARRAY(float, v_log, 16), TS_IN_ARRAY(float, lobe_log, 16),
                                    TS_OUT_ARRAY(float, f, 16), TS_INOUT_ARRAY(float, t, 16)) {
    bool void_texel = false;
    for (int i = 0; i < 16; ++i) {
        f[i] = v_log[i] + lobe_log[i];
        if (isnan(f[i])) void_texel = true;
    }
    if (void_texel)
        for (int i = 0; i < 16; ++i) t[i] = TS_QUIET_NAN_F;
    return !void_texel;
}

// The transfer vector of one texel: T = exp(V_log + F_log), with F_log the lobe's log-SH.
// Any NaN in V_log or F_log (a void texel) gives T = NaN in every coefficient.
TS_INLINE void ts_transfer_vector(TS_IN_ARRAY(float, v_log, 16), TS_IN_ARRAY(float, lobe_log, 16), float threshold,
                                  int max_squarings, TS_INOUT_ARRAY(float, t, 16)) {
    float f[16];
    if (ts_transfer_exponent(v_log, lobe_log, f, t)) ts_sh_exp_hybrid(f, threshold, max_squarings, t);
}

#endif  // TS_SH_EXP_SHARED_H
