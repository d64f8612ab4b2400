#version 450
// The sphere blockers' log-SH on the GPU: one invocation per entry (a receiver seen by one
// mesh), a loop over that mesh's spheres (texels x spheres, no hierarchy), the formulas of the
// CPU kernel core/blockers/sphere_log_sh_kernel.cpp: each cap from its radius and distance
// (ts_sphere_cap_rd, no asin), its log-ZH turned to its direction (ts_zh_rotate), dropped when
// wholly below the receiver's tangent plane. Writes the entry's 16 unscaled sums and the kept
// caps' solid angle, band-sequential [row][entry] (17 rows): the host adds the entries of a
// texel together and applies the ratio attenuation over all of them, as the CPU does for
// several meshes.
#extension GL_GOOGLE_include_directive : require
#define TS_GLSL 1
#include "core/sh/sh_shared.h"
layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Receivers { vec4 receiver[]; };  // xyz, in its mesh's frame
layout(std430, set = 0, binding = 1) readonly buffer Normals { vec4 normal[]; };      // xyz unit normal
layout(std430, set = 0, binding = 2) readonly buffer Ranges { uvec2 range[]; };       // its mesh's spheres: first, count
layout(std430, set = 0, binding = 3) readonly buffer Spheres { vec4 sphere[]; };      // xyz centre, w radius
layout(std430, set = 0, binding = 4) writeonly buffer Sums { float sums[]; };         // [row][entry]

layout(push_constant) uniform Push {
    uint entries;
    float log_eps;
    uint cull_lower_hemisphere;
} p;

const float kTwoPi = 6.283185307179586;

void main() {
    uint t = gl_GlobalInvocationID.x;
    if (t >= p.entries) return;
    vec3 q = receiver[t].xyz;
    vec3 n = normal[t].xyz;
    float sum[16];
    for (int i = 0; i < 16; ++i) sum[i] = 0.0;
    float solid_angle = 0.0;
    uvec2 spheres = range[t];
    for (uint b = spheres.x; b < spheres.x + spheres.y; ++b) {
        vec3 v = sphere[b].xyz - q;
        float r = sphere[b].w;
        float d = length(v);
        float cap[4];  // 1/d, cos, sin, 1 - cos (0, -1, 0, 2 inside)
        ts_sphere_cap_rd(r, d, cap);
        // Culled when the angle between the normal and the axis exceeds 90 deg + theta_b.
        if (p.cull_lower_hemisphere != 0u && dot(v, n) * cap[0] + cap[2] < 0.0) continue;
        vec3 dir = d <= r ? vec3(0.0, 0.0, 1.0) : v * cap[0];
        float zh[4];
        ts_cap_log_zh_omc(cap[1], cap[2], cap[3], p.log_eps, zh);
        float f[16];
        ts_zh_rotate(zh, dir, f);
        for (int i = 0; i < 16; ++i) sum[i] += f[i];
        solid_angle += kTwoPi * cap[3];
    }
    for (int i = 0; i < 16; ++i) sums[uint(i) * p.entries + t] = sum[i];
    sums[16u * p.entries + t] = solid_angle;
}
