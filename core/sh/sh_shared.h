// The single definition of the log-SH formulas, shared by C++ (core/sh) and GLSL (gpu/shaders).
//
// Written in the common subset of C++20 and GLSL 4.50: only the macros of glsl_compat.h, plain
// arithmetic, sqrt/sin/cos/asin, for loops and if. No templates, namespaces, std::, const&,
// float suffixes. docs/method.md derives every formula.
//
// C++ side: do not include this file directly; include core/sh/sh_shared.hpp, which opens
// namespace ts::sh::shared around it (TS_REAL = double, TS_VEC3 = glm::dvec3).
// GLSL side: `#define TS_GLSL 1` then `#include "core/sh/sh_shared.h"` (TS_REAL = float).
//
// Conventions (../shared/design/ARCHITECTURE.md): real orthonormal SH, l = 0..3, 16
// coefficients, index i = l*l + l + m, no Condon-Shortley phase (y_1,1 = +0.4886 x). ENU frame,
// z up; azimuth phi counter-clockwise from +x (east); theta the polar angle from +z.
//
// The function signatures in this file are frozen (the GPU code depends on them).
#ifndef TS_SH_SHARED_H
#define TS_SH_SHARED_H

#include "core/util/glsl_compat.h"

#define TS_SH_COUNT 16

// ---------------------------------------------------------------------------------------
// The 16 real orthonormal SH basis functions at a unit direction d = (x, y, z).
// y_lm = K_lm P_l^|m|(z) * {sqrt2 cos(m phi), 1, sqrt2 sin(|m| phi)} written as polynomials:
// y_i = norm_i * poly_i(d), with the constants (ts_sh_norms) apart from the polynomials
// (ts_sh_poly) so that a sum over many directions can scale once at its end.
TS_INLINE void ts_sh_norms(TS_OUT_ARRAY(TS_REAL, k, 16)) {
    k[0] = 0.28209479177387814;
    k[1] = 0.4886025119029199;
    k[2] = 0.4886025119029199;
    k[3] = 0.4886025119029199;
    k[4] = 1.0925484305920792;
    k[5] = 1.0925484305920792;
    k[6] = 0.31539156525252005;
    k[7] = 1.0925484305920792;
    k[8] = 0.5462742152960396;
    k[9] = 0.5900435899266435;
    k[10] = 2.890611442640554;
    k[11] = 0.4570457994644658;
    k[12] = 0.3731763325901154;
    k[13] = 0.4570457994644658;
    k[14] = 1.445305721320277;
    k[15] = 0.5900435899266435;
}

TS_INLINE void ts_sh_poly(TS_VEC3 d, TS_OUT_ARRAY(TS_REAL, p, 16)) {
    TS_REAL x = d.x;
    TS_REAL yy = d.y;
    TS_REAL z = d.z;
    p[0] = 1.0;
    p[1] = yy;
    p[2] = z;
    p[3] = x;
    p[4] = x * yy;
    p[5] = yy * z;
    p[6] = 3.0 * z * z - 1.0;
    p[7] = x * z;
    p[8] = x * x - yy * yy;
    p[9] = yy * (3.0 * x * x - yy * yy);
    p[10] = x * yy * z;
    p[11] = yy * (5.0 * z * z - 1.0);
    p[12] = z * (5.0 * z * z - 3.0);
    p[13] = x * (5.0 * z * z - 1.0);
    p[14] = z * (x * x - yy * yy);
    p[15] = x * (x * x - 3.0 * yy * yy);
}

TS_INLINE void ts_sh_eval(TS_VEC3 d, TS_OUT_ARRAY(TS_REAL, y, 16)) {
    TS_REAL k[16];
    ts_sh_norms(k);
    ts_sh_poly(d, y);
    for (int i = 0; i < 16; ++i) y[i] = k[i] * y[i];
}

// ---------------------------------------------------------------------------------------
// ZH rotation [Sloan, Luna, Snyder 2005]: a function symmetric about the z axis with ZH
// coefficients zh[l], turned so that its axis points along the unit direction d:
//   f_lm = sqrt(4 pi / (2l+1)) * zh[l] * y_lm(d).
// The factors sqrt(4 pi / (2l+1)), l = 0..3.
TS_INLINE void ts_zh_rotate_norms(TS_OUT_ARRAY(TS_REAL, s, 4)) {
    s[0] = 3.5449077018110318;
    s[1] = 2.046653415892977;
    s[2] = 1.5853309190424043;
    s[3] = 1.3398491713813576;
}

TS_INLINE void ts_zh_rotate(TS_IN_ARRAY(TS_REAL, zh, 4), TS_VEC3 d, TS_OUT_ARRAY(TS_REAL, f, 16)) {
    TS_REAL y[16];
    ts_sh_eval(d, y);
    TS_REAL s[4];
    ts_zh_rotate_norms(s);
    f[0] = s[0] * zh[0] * y[0];
    for (int i = 1; i < 4; ++i) f[i] = s[1] * zh[1] * y[i];
    for (int i = 4; i < 9; ++i) f[i] = s[2] * zh[2] * y[i];
    for (int i = 9; i < 16; ++i) f[i] = s[3] * zh[3] * y[i];
}

// ---------------------------------------------------------------------------------------
// Elevation slice (slides, "Elevation Visibility"): log-visibility log_eps below the horizon
// elevation sigma (radians, [-pi/2, pi/2]), 0 above, i.e. on theta in [pi/2 - sigma, pi].
// Its 4 normalised-Legendre coefficients, c_l = log_eps * int_{-1}^{sin sigma} Phat_l(x) dx
// with Phat_l = sqrt((2l+1)/2) P_l:
//   log_eps * [ (sin s + 1)/sqrt2, -3 cos^2 s / (2 sqrt6), -5 sin s cos^2 s / (2 sqrt10),
//               7 cos^2 s (5 cos^2 s - 4) / (8 sqrt14) ].
TS_INLINE void ts_slice_log_coeffs(TS_REAL sigma, TS_REAL log_eps, TS_OUT_ARRAY(TS_REAL, c, 4)) {
    TS_REAL s = sin(sigma);
    TS_REAL co = cos(sigma);
    TS_REAL c2 = co * co;
    c[0] = log_eps * 0.7071067811865475 * (s + 1.0);
    c[1] = log_eps * -0.6123724356957946 * c2;
    c[2] = log_eps * -0.7905694150420948 * s * c2;
    c[3] = log_eps * 0.23385358667337133 * c2 * (5.0 * c2 - 4.0);
}

// The same slice integrated against every associated Legendre function of the SH basis:
//   e[p] = log_eps * K_l|m| * int_{-1}^{sin sigma} P_l^|m|(x) dx,  p = l(l+1)/2 + |m|,
// (pairs (0,0) (1,0) (1,1) (2,0) (2,1) (2,2) (3,0) (3,1) (3,2) (3,3)). The odd-|m| entries
// need sigma itself (x = sin a substitution), which the 4 Legendre coefficients above cannot
// give; these 10 numbers make the height-field projection exact (ts_hf_add_slice).
// ts_slice_sh_integrals_sc takes s = sin sigma and co = cos sigma from the caller (the CPU's
// vectorised pass derives them from polynomials, core/visibility/small_angle_trig.hpp).
TS_INLINE void ts_slice_sh_integrals_sc(TS_REAL s, TS_REAL co, TS_REAL sigma, TS_REAL log_eps,
                                        TS_OUT_ARRAY(TS_REAL, e, 10)) {
    TS_REAL a = sigma + 1.5707963267948966;  // asin(x) from -1 to s
    TS_REAL sc = s * co;
    TS_REAL c2 = co * co;
    e[0] = log_eps * 0.28209479177387814 * (s + 1.0);
    e[1] = log_eps * 0.4886025119029199 * 0.5 * (s * s - 1.0);
    e[2] = log_eps * 0.3454941494713355 * 0.5 * (sc + a);
    e[3] = log_eps * 0.6307831305050401 * 0.5 * (s * s * s - s);
    e[4] = log_eps * 0.25751613468212636 * (-c2 * co);
    e[5] = log_eps * 0.12875806734106318 * (2.0 + 3.0 * s - s * s * s);
    e[6] = log_eps * 0.7463526651802308 * 0.125 * (5.0 * s * s * s * s - 6.0 * s * s + 1.0);
    e[7] = log_eps * 0.21545345607610045 * 0.1875 * (a - sc * (9.0 - 10.0 * s * s));
    e[8] = log_eps * 0.06813236509555216 * (-3.75 * c2 * c2);
    e[9] = log_eps * 0.027814921575518937 * 1.875 * (sc * (5.0 - 2.0 * s * s) + 3.0 * a);
}

TS_INLINE void ts_slice_sh_integrals(TS_REAL sigma, TS_REAL log_eps, TS_OUT_ARRAY(TS_REAL, e, 10)) {
    ts_slice_sh_integrals_sc(sin(sigma), cos(sigma), sigma, log_eps, e);
}

// Weight of the slice sampled at azimuth phi_k, spacing delta, in SH coefficient of order m,
// when the log-visibility is interpolated linearly in azimuth between adjacent slices: the
// integral of the hat function centred at phi_k times the azimuthal part of y_lm,
//   m = 0: delta;  m > 0: sqrt2 cos(m phi_k) * delta * sinc^2(m delta/2);  m < 0: with sin.
TS_INLINE TS_REAL ts_slice_azimuth_weight(int m, TS_REAL phi_k, TS_REAL delta) {
    if (m == 0) return delta;
    TS_REAL am = m > 0 ? TS_REAL(m) : TS_REAL(-m);
    TS_REAL h = 0.5 * am * delta;
    TS_REAL sinc = sin(h) / h;
    TS_REAL trig = m > 0 ? cos(am * phi_k) : sin(am * phi_k);
    return 1.4142135623730951 * trig * delta * sinc * sinc;
}

// Adds one slice (horizon elevation sigma at azimuth phi_k; slices every delta radians) to the
// log-SH vector f of the height field. Summing all D slices (phi_k = k * 2pi/D) gives the exact
// SH projection of the log-visibility blended linearly in azimuth between slices.
TS_INLINE void ts_hf_add_slice(TS_REAL sigma, TS_REAL phi_k, TS_REAL delta, TS_REAL log_eps,
                               TS_INOUT_ARRAY(TS_REAL, f, 16)) {
    TS_REAL e[10];
    ts_slice_sh_integrals(sigma, log_eps, e);
    for (int l = 0; l < 4; ++l) {
        for (int m = -l; m <= l; ++m) {
            int am = m < 0 ? -m : m;
            f[l * l + l + m] += ts_slice_azimuth_weight(m, phi_k, delta) * e[(l * (l + 1)) / 2 + am];
        }
    }
}

// ---------------------------------------------------------------------------------------
// Sphere blocker [Ren et al. 2006; slides]: half-angle of the blocked cone seen from a
// receiver at distance d from the centre of a sphere of radius r; a receiver inside or on the
// sphere (d <= r) is fully occluded, which is the cap of half-angle pi (the whole sphere).
TS_INLINE TS_REAL ts_sphere_theta_b(TS_REAL r, TS_REAL d) {
    if (d <= r) return TS_PI;
    return asin(r / d);
}

// Log-ZH coefficients of a cap around +z with value log_eps inside, from the cosine and sine
// of its half-angle theta_b:
//   log_eps * [ sqrt(pi)(1 - cos tb), sqrt(3pi)/2 sin^2 tb, sqrt(5pi)/2 cos tb sin^2 tb,
//               sqrt(7pi)/16 (3 + 5 cos 2tb) sin^2 tb ].   theta_b = pi gives the whole sphere.
// 1 - cos tb from the cap's cosine and sine, without the cancellation of 1 - cb for small caps
// (in float a cap of sine 0.01 kept only three digits of it): sin^2 / (1 + cos) while cos > 0.
TS_INLINE TS_REAL ts_one_minus_cos(TS_REAL cb, TS_REAL sb) {
    return cb > 0.0 ? sb * sb / (1.0 + cb) : 1.0 - cb;
}

// Those coefficients with 1 - cos tb given (ts_cap_log_zh_omc; ts_sphere_cap_rd has it without
// a second division), as c_l = log_eps * norm_l * shape_l: the constants (ts_cap_zh_norms) apart from the shape of the
// cap (ts_cap_zh_shape), so that a sum over many caps can scale once at its end.
TS_INLINE void ts_cap_zh_norms(TS_OUT_ARRAY(TS_REAL, k, 4)) {
    k[0] = 1.7724538509055159;
    k[1] = 1.5349900619197328;
    k[2] = 1.9816636488030055;
    k[3] = 0.29309200623967196;
}

TS_INLINE void ts_cap_zh_shape(TS_REAL cb, TS_REAL sb, TS_REAL omc, TS_OUT_ARRAY(TS_REAL, c, 4)) {
    TS_REAL s2 = sb * sb;
    c[0] = omc;
    c[1] = s2;
    c[2] = cb * s2;
    c[3] = (3.0 + 5.0 * (2.0 * cb * cb - 1.0)) * s2;
}

TS_INLINE void ts_cap_log_zh_omc(TS_REAL cb, TS_REAL sb, TS_REAL omc, TS_REAL log_eps, TS_OUT_ARRAY(TS_REAL, c, 4)) {
    TS_REAL k[4];
    ts_cap_zh_norms(k);
    ts_cap_zh_shape(cb, sb, omc, c);
    for (int l = 0; l < 4; ++l) c[l] = log_eps * k[l] * c[l];
}

// From the cosine and sine alone.
TS_INLINE void ts_cap_log_zh(TS_REAL cb, TS_REAL sb, TS_REAL log_eps, TS_OUT_ARRAY(TS_REAL, c, 4)) {
    ts_cap_log_zh_omc(cb, sb, ts_one_minus_cos(cb, sb), log_eps, c);
}

// The same from the half-angle itself.
TS_INLINE void ts_sphere_log_zh(TS_REAL theta_b, TS_REAL log_eps, TS_OUT_ARRAY(TS_REAL, c, 4)) {
    ts_cap_log_zh(cos(theta_b), sin(theta_b), log_eps, c);
}

// The cap a sphere of radius r subtends from a receiver at distance d from its centre, with one
// division: cap = [1/d, cos tb, sin tb, 1 - cos tb]. With t = sqrt((d - r)(d + r)) (d - r is
// exact in floating point near grazing, where the textbook sqrt(1 - (r/d)^2) would amplify the
// rounding of r/d by tan tb) and k = 1/(d (d + t)):
//   1/d = (d + t) k,  cos tb = t/d,  sin tb = r/d,  1 - cos tb = (d - t)/d = r^2 k,
// the last without the cancellation of 1 - cos for small caps. Inside or on the sphere (d <= r)
// the cap is the whole sphere: [0, -1, 0, 2]. Selects, no branch, so that CPU kernels vectorise
// it across spheres.
TS_INLINE void ts_sphere_cap_rd(TS_REAL r, TS_REAL d, TS_OUT_ARRAY(TS_REAL, cap, 4)) {
    bool inside = d <= r;
    TS_REAL t = sqrt(inside ? 0.0 : (d - r) * (d + r));
    TS_REAL k = inside ? 0.0 : 1.0 / (d * (d + t));
    cap[0] = (d + t) * k;
    cap[1] = inside ? -1.0 : t * cap[0];
    cap[2] = r * cap[0];
    cap[3] = inside ? 2.0 : r * r * k;
}

// The same straight from the sphere's radius r and the distance d to its centre, without an
// inverse sine (ts_sphere_cap_rd). GPU asin is loose (the Vulkan spec
// allows thousands of ulp; llvmpipe is 4e-4 rad off near 1), so shaders use this form.
// A receiver inside or on the sphere (d <= r) sees the whole sphere blocked (tb = pi).
TS_INLINE void ts_sphere_log_zh_rd(TS_REAL r, TS_REAL d, TS_REAL log_eps, TS_OUT_ARRAY(TS_REAL, c, 4)) {
    TS_REAL cap[4];
    ts_sphere_cap_rd(r, d, cap);
    ts_cap_log_zh_omc(cap[1], cap[2], cap[3], log_eps, c);
}

// Log-SH vector of a sphere blocker: log-ZH of its cap rotated to the unit direction dir from
// the receiver to the sphere's centre.
TS_INLINE void ts_sphere_log_sh(TS_REAL theta_b, TS_VEC3 dir, TS_REAL log_eps, TS_OUT_ARRAY(TS_REAL, f, 16)) {
    TS_REAL zh[4];
    ts_sphere_log_zh(theta_b, log_eps, zh);
    ts_zh_rotate(zh, dir, f);
}

// 16-term double-product integral <a, b> = int a(w) b(w) dw of two SH-projected functions.
TS_INLINE TS_REAL ts_sh_dot(TS_IN_ARRAY(TS_REAL, a, 16), TS_IN_ARRAY(TS_REAL, b, 16)) {
    TS_REAL s = 0.0;
    for (int i = 0; i < 16; ++i) s += a[i] * b[i];
    return s;
}

#endif  // TS_SH_SHARED_H
