#version 450
// log-SH visibility per texel from its D horizons: the sum over slices of ts_hf_add_slice
// (core/sh/sh_shared.h), evaluated as the CPU's SliceProjector does: ts_slice_sh_integrals per
// slice here, and the slices' ts_slice_azimuth_weight from a D x 16 table the host computes with
// the same shared formula (16 sines and cosines per slice were 90% of this stage's time).
// Band-sequential output [coefficient][texel]; NaN coefficients for void receivers.
#extension GL_GOOGLE_include_directive : require
#define TS_GLSL 1
#include "core/sh/sh_shared.h"
layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Horizons { float horizon[]; };  // [d][texel]
layout(std430, set = 0, binding = 1) writeonly buffer LogSh { float log_sh[]; };      // [i][texel]
layout(std430, set = 0, binding = 2) readonly buffer Weights { float weight[]; };     // [d][i]

layout(push_constant) uniform Push {
    uint texels;
    int directions;
    float log_eps;
} p;

// Which of ts_slice_sh_integrals' 10 values coefficient i = l*l + l + m takes: l(l+1)/2 + |m|.
const int kIntegral[16] = int[16](0, 2, 1, 2, 5, 4, 3, 4, 5, 9, 8, 7, 6, 7, 8, 9);

void main() {
    uint t = gl_GlobalInvocationID.x;
    if (t >= p.texels) return;
    float f[16];
    for (int i = 0; i < 16; ++i) f[i] = 0.0;
    bool is_void = false;
    for (int d = 0; d < p.directions; ++d) {
        float sigma = horizon[uint(d) * p.texels + t];
        if (isnan(sigma)) { is_void = true; break; }
        float e[10];
        ts_slice_sh_integrals(sigma, p.log_eps, e);
        for (int i = 0; i < 16; ++i) f[i] += weight[d * 16 + i] * e[kIntegral[i]];
    }
    for (int i = 0; i < 16; ++i) log_sh[uint(i) * p.texels + t] = is_void ? uintBitsToFloat(0x7fc00000u) : f[i];
}
