#version 450
// Evaluates core/visibility/sun_disc_shared.h (the sun disc's visible fraction above a horizon)
// for a buffer of x = (e - h) / r in float, so tests/gpu/sun_disc_agreement_test.cpp can compare
// with the C++ double evaluation.
#extension GL_GOOGLE_include_directive : require
#define TS_GLSL 1
#include "core/visibility/sun_disc_shared.h"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Cases { float cases[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Results { float results[]; };

layout(push_constant) uniform Push { uint count; } push;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;
    results[i] = ts_sun_disc_fraction(cases[i]);
}
