#version 450
// Evaluates core/raster/display_shared.h (the filmic gain and ts_display, as the flythrough's
// display_code) for a buffer of exposed RGB pixels in float, so
// tests/gpu/display_agreement_test.cpp can compare with the C++ float evaluation.
#extension GL_GOOGLE_include_directive : require
#define TS_GLSL 1
#include "core/raster/display_shared.h"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Inputs { float inputs[]; };  // r, g, b per pixel
// Per pixel: the gain of its clamped channels, then ts_display's three values.
layout(std430, set = 0, binding = 1) writeonly buffer Results { float results[]; };

layout(push_constant) uniform Push { uint count; } push;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;
    vec3 x = vec3(inputs[3 * i], inputs[3 * i + 1], inputs[3 * i + 2]);
    vec3 c = max(x, vec3(0.0));
    vec3 d = ts_display(x);
    results[4 * i] = ts_display_gain(c.r, c.g, c.b);
    results[4 * i + 1] = d.r;
    results[4 * i + 2] = d.g;
    results[4 * i + 3] = d.b;
}
