#pragma once
// SH exponentiation: given log-SH coefficients f, the order-4 SH coefficients of exp(f),
// computed with SH products (sh_product.hpp) as in Ren et al. 2006, "Real-time soft shadows
// in dynamic scenes using spherical harmonic exponentiation". docs/method.md compares the
// methods (error against the exact exp(f) projected, and cost).
//
// Hot path: float arrays, no allocation, no exceptions. Results are always finite: scaling
// and squaring keeps a separate log-scale so intermediate vectors never overflow, the final
// scalar exp() is clamped at exp(80), and a Taylor series stops adding terms that would
// overflow (its error is then large but finite; any non-finite input yields zeros).
#include "core/sh/exp_method.hpp"
#include "core/sh/sh_basis.hpp"

namespace ts::sh {

struct ExpOptions {
    int taylor_order = 8;             // highest power for taylor and dc_isolation
    int squaring_base_order = 3;      // Taylor order on f / 2^k in scaling_squaring
    float squaring_threshold = 1.0f;  // scale until |f / 2^k| <= this (scaling_squaring)
    float hybrid_threshold = 1.0f;    // optimal linear alone up to this non-DC magnitude
    int max_squarings = 24;
};

void sh_exp(ExpMethod method, const float* f_log, float* out, const ExpOptions& options = {});

void exp_taylor(const float* f, float* out, int order);
void exp_dc_isolation(const float* f, float* out, int order);
void exp_optimal_linear(const float* f, float* out);
void exp_scaling_squaring(const float* f, float* out, int base_order, float threshold, int max_squarings);
void exp_hybrid(const float* f, float* out, float threshold, int max_squarings);

// The fitted optimal-linear coefficients at non-DC magnitude m (linear interpolation in the
// committed table optimal_linear_table.inc; clamped beyond its last magnitude).
struct LinearCoeffs {
    float a, b;
};
LinearCoeffs optimal_linear_coeffs(float magnitude);
float optimal_linear_max_magnitude();

}  // namespace ts::sh
