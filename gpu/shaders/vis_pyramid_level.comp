#version 450
// One level of the mean height pyramid from the level below it (core/terrain/height_pyramid.cpp,
// downsample_2x2 with use_max false): each texel the mean of the valid texels of its 2x2 block
// (fewer at an odd last column or row), NaN where all are voids. The CPU sums the (at most four)
// floats in double, exactly, and rounds the mean once; here the exact sum is a float pair
// (two_sum) and the mean is rounded from it, so levels agree with the CPU's to the last bit
// except in rare ties of float rounding.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 8, local_size_y = 8) in;

#define PYRAMID_COARSE_ACCESS
#include "gpu/visibility/vis_pyramid_levels.glsl"

layout(push_constant) uniform Push {
    int dst;  // the level written; reads level dst - 1
} p;

vec2 two_sum(float a, float b) {
    precise float s = a + b;
    precise float bb = s - a;
    precise float e = (a - (s - bb)) + (b - bb);
    return vec2(s, e);
}
vec2 split(float a) {  // Veltkamp: halves whose products are exact
    precise float c = 4097.0 * a;
    precise float hi = c - (c - a);
    precise float lo = a - hi;
    return vec2(hi, lo);
}
vec2 two_prod(float a, float b) {
    precise float prod = a * b;
    vec2 sa = split(a), sb = split(b);
    precise float e = ((sa.x * sb.x - prod) + sa.x * sb.y + sa.y * sb.x) + sa.y * sb.y;
    return vec2(prod, e);
}

void main() {
    int c = int(gl_GlobalInvocationID.x), r = int(gl_GlobalInvocationID.y);
    int w = levels[p.dst].width, h = levels[p.dst].height;
    if (c >= w || r >= h) return;
    int sw = levels[p.dst - 1].width, sh = levels[p.dst - 1].height;
    int c0 = 2 * c, c1 = 2 * c + 1, r0 = 2 * r, r1 = min(2 * r + 1, sh - 1);
    bool has_c1 = c1 < sw, has_r1 = r1 != r0;
    float v[4];
    int n = 0;
    v[n++] = level_at(p.dst - 1, c0, r0);
    if (has_c1) v[n++] = level_at(p.dst - 1, c1, r0);
    if (has_r1) v[n++] = level_at(p.dst - 1, c0, r1);
    if (has_r1 && has_c1) v[n++] = level_at(p.dst - 1, c1, r1);
    // The exact sum of the valid texels as hi + lo (|lo| small): two_sum keeps each addition's
    // rounding error, and four floats' errors add up exactly in lo for heights of a DEM.
    precise float hi = 0.0, lo = 0.0;
    int valid = 0;
    for (int k = 0; k < n; ++k) {
        if (isnan(v[k])) continue;
        vec2 s = two_sum(hi, v[k]);
        hi = s.x;
        lo += s.y;
        ++valid;
    }
    float mean;
    if (valid == 0) {
        mean = uintBitsToFloat(0x7fc00000u);
    } else {
        vec2 s = two_sum(hi, lo);  // s.x: the sum rounded once
        if (valid == 3) {
            // One step of long division in float pairs: q, then the remainder's share.
            precise float q = s.x / 3.0;
            vec2 qp = two_prod(q, 3.0);
            precise float rem = ((s.x - qp.x) - qp.y) + s.y;
            mean = q + rem / 3.0;
        } else {
            // / 1, 2, 4 is exact: the rounded sum's mean is the rounded mean. The sum's own
            // rounding is kept in s.y, which can matter only at a tie: add it back there.
            mean = (s.x + s.y) / float(valid);
        }
    }
    uint i = uint(r) * uint(w) + uint(c);
    if (p.dst == 1) level1[i] = mean;
    else levels2[levels[p.dst].offset + i] = mean;
}
