#version 450
// Evaluates core/raster/display_shared.h (filmic, sRGB OETF) for a buffer of exposed values in
// float, so tests/gpu/display_agreement_test.cpp can compare with the C++ float evaluation.
#extension GL_GOOGLE_include_directive : require
#define TS_GLSL 1
#include "core/raster/display_shared.h"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Inputs { float inputs[]; };
// Per input: filmic(x), srgb_oetf(x), srgb_oetf(filmic(x)).
layout(std430, set = 0, binding = 1) writeonly buffer Results { float results[]; };

layout(push_constant) uniform Push { uint count; } push;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;
    float x = inputs[i];
    float f = ts_filmic(x);
    results[3 * i] = f;
    results[3 * i + 1] = ts_srgb_oetf(x);
    results[3 * i + 2] = ts_srgb_oetf(f);
}
