#version 450
// The aircraft's colour: its material's albedo / pi times the irradiance of the sky the terrain
// lets reach its centre (that SH against the clamped cosine turned to the normal with
// ts_zh_rotate, core/sh/sh_shared.h, the one SH definition of C++ and GLSL) and of the sun times
// the terrain's visible fraction of its disc there. Its own spheres' shadows are not in yet
// (docs/flythrough.md).
#extension GL_GOOGLE_include_directive : require
#define TS_GLSL 1
#include "core/sh/sh_shared.h"
#include "gpu/fly/fly_frame.glsl"

layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec3 v_color;
layout(location = 0) out vec4 out_color;

void main() {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;  // soups have either winding; light the side we see
    // The clamped cosine max(0, cos) projected to order 4: sqrt(pi)/2, sqrt(pi/3), sqrt(5 pi)/8, 0.
    float lobe[4] = float[4](0.886226925, 1.023326708, 0.495415912, 0.0);
    float f[16];
    ts_zh_rotate(lobe, n, f);
    vec3 e_sky = vec3(0.0);
    for (int i = 0; i < 16; ++i) e_sky += f[i] * frame.sky_sh[i].rgb;
    float cos_r = frame.sun_direction.w;
    float sun_solid_angle = 6.283185307 * (1.0 - cos_r);
    vec3 e_sun = frame.sun_radiance.rgb * sun_solid_angle * max(dot(n, frame.sun_direction.xyz), 0.0) *
                 frame.aircraft_light.x;
    vec3 l = v_color / 3.14159265 * (max(e_sky, vec3(0.0)) + e_sun);
    out_color = vec4(display_code(l * frame.sun_radiance.w), 1.0);
}
