#version 450
// The terrain's colour: the per-texel radiance of this sun and sky (the CPU's fused diffuse
// pass over the cached transfer vectors, core/render/diffuse_shading.hpp), bilinear, then
// aerial perspective towards the sky's horizon radiance in the ray's azimuth (as
// core/render/perspective_view.hpp; from the vertex shader), exposure and the display curve.
#extension GL_GOOGLE_include_directive : require
#include "gpu/fly/fly_frame.glsl"

layout(location = 0) in vec2 v_texel;
layout(location = 1) in vec3 v_haze;
layout(location = 2) in float v_transmittance;
layout(location = 0) out vec4 out_color;

vec3 texel_radiance(int c, int r) {
    uvec2 p = radiance[r * int(frame.grid.x) + c];
    return vec3(unpackHalf2x16(p.x), unpackHalf2x16(p.y).x);
}

void main() {
    int w = int(frame.grid.x), h = int(frame.grid.y);
    vec2 t = clamp(v_texel, vec2(0.0), frame.grid.xy - 1.0);
    int c0 = min(int(floor(t.x)), w - 2), r0 = min(int(floor(t.y)), h - 2);
    vec2 f = t - vec2(c0, r0);
    vec3 l = mix(mix(texel_radiance(c0, r0), texel_radiance(c0 + 1, r0), f.x),
                 mix(texel_radiance(c0, r0 + 1), texel_radiance(c0 + 1, r0 + 1), f.x), f.y);
    l = l * v_transmittance + v_haze * (1.0 - v_transmittance);
    out_color = vec4(display_code(l * frame.sun_radiance.w), 1.0);
}
