#version 450
// The sphere blockers' log-SH on the GPU: one invocation per receiver, a loop over every sphere
// (texels x spheres, no hierarchy), the same formulas and attenuation as the CPU kernel
// core/blockers/sphere_log_sh_kernel.cpp: each cap's log-ZH from its radius and distance
// (ts_sphere_log_zh_rd, no asin) turned to its direction (ts_zh_rotate), dropped when wholly
// below the receiver's tangent plane, the sum scaled by 2 pi / (sum of the kept caps' solid
// angles) when that exceeds 2 pi. Adds to the receiver's 16 coefficients, band-sequential
// [coefficient][receiver] as the terrain's log-SH is laid out.
#extension GL_GOOGLE_include_directive : require
#define TS_GLSL 1
#include "core/sh/sh_shared.h"
layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Receivers { vec4 receiver[]; };  // xyz position
layout(std430, set = 0, binding = 1) readonly buffer Normals { vec4 normal[]; };      // xyz unit normal
layout(std430, set = 0, binding = 2) readonly buffer Spheres { vec4 sphere[]; };      // xyz centre, w radius
layout(std430, set = 0, binding = 3) buffer LogSh { float log_sh[]; };                // [i][receiver]

layout(push_constant) uniform Push {
    uint receivers;
    uint spheres;
    float log_eps;
    uint cull_lower_hemisphere;
    uint solid_angle_ratio;
} p;

const float kTwoPi = 6.283185307179586;

void main() {
    uint t = gl_GlobalInvocationID.x;
    if (t >= p.receivers) return;
    vec3 q = receiver[t].xyz;
    vec3 n = normal[t].xyz;
    float sum[16];
    for (int i = 0; i < 16; ++i) sum[i] = 0.0;
    float solid_angle = 0.0;
    for (uint b = 0u; b < p.spheres; ++b) {
        vec3 v = sphere[b].xyz - q;
        float r = sphere[b].w;
        float d = length(v);
        bool inside = d <= r;
        float inv = inside ? 0.0 : 1.0 / d;
        float sb = inside ? 0.0 : r * inv;
        // Culled when the angle between the normal and the axis exceeds 90 deg + theta_b.
        if (p.cull_lower_hemisphere != 0u && !inside && dot(v, n) * inv < -sb) continue;
        float cb = inside ? -1.0 : sqrt((d - r) * (d + r)) * inv;
        vec3 dir = inside ? vec3(0.0, 0.0, 1.0) : v * inv;
        float zh[4];
        ts_sphere_log_zh_rd(r, d, p.log_eps, zh);
        float f[16];
        ts_zh_rotate(zh, dir, f);
        for (int i = 0; i < 16; ++i) sum[i] += f[i];
        solid_angle += kTwoPi * ts_one_minus_cos(cb, sb);
    }
    float scale = p.solid_angle_ratio != 0u && solid_angle > kTwoPi ? kTwoPi / solid_angle : 1.0;
    for (int i = 0; i < 16; ++i) log_sh[uint(i) * p.receivers + t] += scale * sum[i];
}
