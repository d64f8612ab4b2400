#version 450
// Sky view factor and visible sky fraction of a horizontal receiver from its D horizons, with
// linear wedges between azimuths: the formulas are core/visibility/sky_shared.h, the same text
// the CPU (sky_integrals.cpp, WedgeRule::linear) compiles.
#extension GL_GOOGLE_include_directive : require
#define TS_GLSL 1
#include "core/visibility/sky_shared.h"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Horizons { float horizon[]; };  // [d][texel]
layout(std430, set = 0, binding = 1) writeonly buffer Svf { float svf[]; };
layout(std430, set = 0, binding = 2) writeonly buffer SkyVisible { float sky_visible[]; };

layout(push_constant) uniform Push {
    uint texels;
    int directions;
} p;

void main() {
    uint t = gl_GlobalInvocationID.x;
    if (t >= p.texels) return;
    float cos2 = 0.0, sn = 0.0;
    bool is_void = false;
    for (int d = 0; d < p.directions; ++d) {
        float a = horizon[uint(d) * p.texels + t];
        float b = horizon[uint((d + 1) % p.directions) * p.texels + t];
        if (isnan(a)) { is_void = true; break; }
        cos2 += ts_wedge_mean_cos2(a, b);
        sn += ts_wedge_mean_sin(a, b);
    }
    float nan = uintBitsToFloat(0x7fc00000u);
    svf[t] = is_void ? nan : cos2 / float(p.directions);
    sky_visible[t] = is_void ? nan : 1.0 - sn / float(p.directions);
}
