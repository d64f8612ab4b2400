#version 450
// Evaluates every function of core/sh/sh_shared.h for a buffer of cases, in float, so the
// GPU agreement test can compare with the C++ (double) evaluation of the same text.
// The output layout per case is kSegments in tests/gpu/sh_agreement_test.cpp; keep both equal.
#extension GL_GOOGLE_include_directive : require
#define TS_GLSL 1
#include "core/sh/sh_shared.h"

layout(local_size_x = 64) in;

// 12 floats, 48 bytes, no vec3 in it: the std430 layout is then the C++ struct's.
struct Case {
    float dx, dy, dz;  // a unit direction
    float sigma;       // horizon elevation, radians
    float theta_b;     // sphere cap half-angle, radians
    float r, dist;     // sphere radius and centre distance
    float phi_k;       // slice azimuth, radians
    float delta;       // slice spacing, radians
    float log_eps;
    float pad0, pad1;
};

layout(std430, set = 0, binding = 0) readonly buffer Cases { Case cases[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Results { float results[]; };

layout(push_constant) uniform Push {
    uint count;
    uint results_per_case;
} push;

void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;
    const Case k = cases[i];
    const vec3 d = vec3(k.dx, k.dy, k.dz);
    uint o = i * push.results_per_case;

    float y[16];
    ts_sh_eval(d, y);
    for (int j = 0; j < 16; ++j) results[o++] = y[j];

    float c[4];
    ts_slice_log_coeffs(k.sigma, k.log_eps, c);
    for (int j = 0; j < 4; ++j) results[o++] = c[j];

    float e[10];
    ts_slice_sh_integrals(k.sigma, k.log_eps, e);
    for (int j = 0; j < 10; ++j) results[o++] = e[j];

    float zh[4];
    ts_sphere_log_zh(k.theta_b, k.log_eps, zh);
    for (int j = 0; j < 4; ++j) results[o++] = zh[j];

    float rotated[16];
    ts_zh_rotate(c, d, rotated);
    for (int j = 0; j < 16; ++j) results[o++] = rotated[j];

    float sphere[16];
    ts_sphere_log_sh(k.theta_b, d, k.log_eps, sphere);
    for (int j = 0; j < 16; ++j) results[o++] = sphere[j];

    float zh_rd[4];
    ts_sphere_log_zh_rd(k.r, k.dist, k.log_eps, zh_rd);
    for (int j = 0; j < 4; ++j) results[o++] = zh_rd[j];

    for (int m = -3; m <= 3; ++m) results[o++] = ts_slice_azimuth_weight(m, k.phi_k, k.delta);

    float f[16] = y;  // inout: the slice is added to the basis values
    ts_hf_add_slice(k.sigma, k.phi_k, k.delta, k.log_eps, f);
    for (int j = 0; j < 16; ++j) results[o++] = f[j];

    results[o++] = ts_sh_dot(y, sphere);
}
