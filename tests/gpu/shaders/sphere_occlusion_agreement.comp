#version 450
// Evaluates core/blockers/sphere_occlusion_shared.h (a sphere's cover of the sun's disc and of
// the cosine-weighted sky) for a buffer of cases in float, so
// tests/gpu/sphere_occlusion_agreement_test.cpp can compare with the C++ double evaluation.
#extension GL_GOOGLE_include_directive : require
#define TS_GLSL 1
#include "core/blockers/sphere_occlusion_shared.h"

layout(local_size_x = 64) in;

// Per case 4 vec4: sphere (centre, radius), receiver (xyz, the sun's angular radius), the sun's
// unit direction, the receiver's unit normal.
layout(std430, set = 0, binding = 0) readonly buffer Cases { vec4 cases[]; };
// Per case: sun cover, sky cover.
layout(std430, set = 0, binding = 1) writeonly buffer Results { float results[]; };

layout(push_constant) uniform Push { uint count; } push;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;
    vec4 sphere = cases[4 * i], receiver = cases[4 * i + 1];
    vec3 sun = cases[4 * i + 2].xyz, normal = cases[4 * i + 3].xyz;
    results[2 * i] = ts_sphere_sun_cover(sphere.xyz, sphere.w, receiver.xyz, sun, receiver.w);
    results[2 * i + 1] = ts_sphere_sky_cover(sphere.xyz, sphere.w, receiver.xyz, normal);
}
