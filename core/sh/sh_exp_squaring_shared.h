// The single definition of the scaling-and-squaring SH exponentiation (Taylor series on f / 2^k,
// then k SH squarings; Ren et al. 2006), shared by C++ (core/render/transfer.cpp) and GLSL
// (gpu/shaders/render_transfer.comp), next to the hybrid method of core/sh/sh_exp_shared.h.
//
// Float in both languages, for the reason sh_exp_shared.h gives. It follows core/sh/sh_exp.cpp's
// exp_scaling_squaring step for step (no DC isolation: k comes from the norm of all 16
// coefficients; Taylor series of base_order on the scaled vector, a term that would overflow
// stops the series; normalised squarings with the log-norm kept apart; the final scale clamped
// at exp(80)), except that k is found by exact halving instead of ceil(log2(.)) and the products
// are sh_product_shared.h's written-out tensor (same sums, another order: rounding apart).
//
// C++ side: include core/sh/sh_exp_squaring_shared.hpp (namespace ts::sh::exp_shared).
// GLSL side: `#define TS_GLSL 1`, the TS_LINEAR_* macros if wanted, then
// `#include "core/sh/sh_exp_squaring_shared.h"` (it includes sh_exp_shared.h).
#ifndef TS_SH_EXP_SQUARING_SHARED_H
#define TS_SH_EXP_SQUARING_SHARED_H

#include "core/sh/sh_exp_shared.h"

// Taylor terms whose norm reaches this stop the series (sh_exp.cpp's kTermOverflow).
#define TS_TAYLOR_TERM_OVERFLOW 1e30f

// The exponentiation methods ts_transfer_vector_by runs (a push constant on the GPU).
#define TS_TRANSFER_EXP_HYBRID 0
#define TS_TRANSFER_EXP_SCALING_SQUARING 1

// sum_{n=0}^{order} f^n / n! in the SH product, stopping before a term would overflow.
TS_INLINE void ts_sh_taylor(TS_IN_ARRAY(float, f, 16), int order, TS_OUT_ARRAY(float, result, 16)) {
    float term[16];
    float next[16];
    for (int i = 0; i < 16; ++i) {
        result[i] = 0.0f;
        term[i] = f[i];
    }
    result[0] = TS_SQRT_4PI_F;  // f^0: the constant function 1
    for (int n = 1; n <= order; ++n) {
        if (n > 1) {
            ts_sh_product(term, f, next);
            float inv = 1.0f / float(n);
            for (int i = 0; i < 16; ++i) term[i] = next[i] * inv;
        }
        if (!(ts_sh_norm(term) < TS_TAYLOR_TERM_OVERFLOW)) break;
        for (int i = 0; i < 16; ++i) result[i] += term[i];
    }
}

// exp of the log-SH vector f by scaling and squaring:
//  - scaling: k = the fewest halvings that bring |f| (all 16 coefficients) to at most
//    `threshold` (at most max_squarings);
//  - Taylor series of order base_order on f / 2^k;
//  - squaring: k SH squarings, each renormalised with its log-norm kept apart; the scale is
//    applied once at the end, clamped at exp(80).
// Non-finite input, or a result that is not finite, gives zeros (as sh::sh_exp).
TS_INLINE void ts_sh_exp_scaling_squaring(TS_IN_ARRAY(float, f, 16), int base_order, float threshold,
                                          int max_squarings, TS_OUT_ARRAY(float, result, 16)) {
    for (int i = 0; i < 16; ++i) result[i] = 0.0f;
    if (!ts_sh_all_finite(f)) return;
    float m = ts_sh_norm(f);
    float scale[1];
    int k = ts_sh_halvings(m, threshold, max_squarings, scale);
    float scaled[16];
    for (int i = 0; i < 16; ++i) scaled[i] = f[i] * scale[0];
    float g[16];
    ts_sh_taylor(scaled, base_order, g);
    float log_scale[1];
    if (!ts_sh_square_k_times(g, k, log_scale)) return;  // zeros
    float e = exp(min(log_scale[0], TS_EXP_MAX_LOG_SCALE));
    for (int i = 0; i < 16; ++i) result[i] = e * g[i];
    if (!ts_sh_all_finite(result))
        for (int i = 0; i < 16; ++i) result[i] = 0.0f;
}

// The transfer vector of one texel, T = exp(V_log + F_log), by `method` (TS_TRANSFER_EXP_*):
// hybrid with hybrid_threshold, or scaling and squaring with squaring_base_order and
// squaring_threshold; at most max_squarings squarings either way. Any NaN in V_log or F_log (a
// void texel) gives T = NaN in every coefficient.
TS_INLINE void ts_transfer_vector_by(int method, TS_IN_ARRAY(float, v_log, 16), TS_IN_ARRAY(float, lobe_log, 16),
                                     float hybrid_threshold, int squaring_base_order, float squaring_threshold,
                                     int max_squarings, TS_OUT_ARRAY(float, t, 16)) {
    if (method == TS_TRANSFER_EXP_HYBRID) {
        ts_transfer_vector(v_log, lobe_log, hybrid_threshold, max_squarings, t);
        return;
    }
    float f[16];
    if (ts_transfer_exponent(v_log, lobe_log, f, t))
        ts_sh_exp_scaling_squaring(f, squaring_base_order, squaring_threshold, max_squarings, t);
}

#endif  // TS_SH_EXP_SQUARING_SHARED_H
