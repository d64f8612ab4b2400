#version 450
// The transfer vector of every texel (core/render/transfer.hpp on the GPU):
//   T = exp_SH(V_log + rotate(F_log, axis))
// with the lobe's log-ZH turned to its axis by ts_zh_rotate (core/sh/sh_shared.h) and the
// hybrid (core/sh/sh_exp_shared.h) or scaling-and-squaring (core/sh/sh_exp_squaring_shared.h)
// exponentiation, the text the CPU path compiles too.
// Band-sequential [coefficient][texel] in and out; NaN anywhere in a texel's log gives NaN T.
#extension GL_GOOGLE_include_directive : require
#define TS_GLSL 1
layout(local_size_x = 64) in;

// The optimal-linear table {magnitude, a, b} per row, uploaded by the host from the C++ view of
// sh_exp_shared.h's own array (a constant array indexed per invocation is slow on llvmpipe).
layout(std430, set = 0, binding = 4) readonly buffer LinearTable { float linear_table[]; };
#define TS_LINEAR_M(i) linear_table[3 * (i)]
#define TS_LINEAR_A(i) linear_table[3 * (i) + 1]
#define TS_LINEAR_B(i) linear_table[3 * (i) + 2]
#include "core/sh/sh_shared.h"
#include "core/sh/sh_exp_squaring_shared.h"

layout(std430, set = 0, binding = 0) readonly buffer LogVisibility { float log_vis[]; };  // [i][texel]
layout(std430, set = 0, binding = 1) readonly buffer LobeAxis { float axis[]; };          // [texel][3]
layout(std430, set = 0, binding = 2) readonly buffer LobeZh { float lobe_zh[]; };        // [texel][4] or [4]
layout(std430, set = 0, binding = 3) writeonly buffer Transfer { float transfer[]; };    // [i][stride]

layout(push_constant) uniform Push {
    uint texels;
    uint stride;          // texels per plane of T (padded to four for render_shade.comp)
    uint uniform_lobe;
    float threshold;      // hybrid: optimal linear alone up to this non-DC magnitude
    int max_squarings;
    int method;           // TS_TRANSFER_EXP_HYBRID or TS_TRANSFER_EXP_SCALING_SQUARING
    float squaring_threshold;  // scaling_squaring: halve f until its norm is at most this
    int squaring_base_order;   // scaling_squaring: Taylor order on f / 2^k
} p;

void main() {
    uint t = gl_GlobalInvocationID.x;
    if (t >= p.texels) return;
    float v[16];
    for (int i = 0; i < 16; ++i) v[i] = log_vis[uint(i) * p.texels + t];
    float zh[4];
    uint z0 = p.uniform_lobe != 0u ? 0u : 4u * t;
    for (int l = 0; l < 4; ++l) zh[l] = lobe_zh[z0 + uint(l)];
    float lobe[16];
    ts_zh_rotate(zh, vec3(axis[3u * t], axis[3u * t + 1u], axis[3u * t + 2u]), lobe);
    float result[16];
    ts_transfer_vector_by(p.method, v, lobe, p.threshold, p.squaring_base_order, p.squaring_threshold, p.max_squarings,
                          result);
    for (int i = 0; i < 16; ++i) transfer[uint(i) * p.stride + t] = result[i];
}
