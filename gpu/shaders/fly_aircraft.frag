#version 450
// The aircraft's colour: its material's albedo / pi times the irradiance of the sky the terrain
// lets reach its centre (that SH against the clamped cosine turned to the normal with
// ts_zh_rotate, core/sh/sh_shared.h, the one SH definition of C++ and GLSL) and of the sun times
// the terrain's visible fraction of its disc there and the fraction its own spheres leave (the
// spheres that do not hold the fragment: a surface point lies inside the sphere bounding it;
// core/blockers/sphere_occlusion_shared.h, as core/blockers/self_shadow.hpp on the CPU), the
// sky's part times the share of the sky those spheres leave (per vertex, interpolated).
#extension GL_GOOGLE_include_directive : require
#define TS_GLSL 1
#include "core/sh/sh_shared.h"
#include "core/blockers/sphere_occlusion_shared.h"
#include "gpu/fly/fly_frame.glsl"

layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec3 v_color;
layout(location = 2) in vec3 v_rel;
// The sky share the aircraft's own spheres leave, per vertex (core/blockers/self_sky_shadow.hpp,
// computed once per aircraft): the normal's side, the other side.
layout(location = 3) in vec2 v_self_sky;
layout(location = 0) out vec4 out_color;

// The sun's disc fraction the aircraft's own spheres leave at `p` (unit normal `n`, the side
// seen). Spheres whose centre lies behind the tangent plane are not blockers: the bounding
// spheres of a thin part (a wing, 0.2 m thick under spheres of its 1.5 m chord) bulge above its
// own surface and would speckle it with their caps; what shadows a surface stands in front of it.
float self_shadow_sun(vec3 p, vec3 n) {
    vec3 s = frame.sun_direction.xyz;
    float alpha = frame.aircraft_shadow.z;
    float visible = 1.0;
    int count = int(frame.aircraft_shadow.x);
    // The hierarchy walk, its subtrees pruned by the sun cone; a node holding the point is
    // entered (the cone meets it) but a leaf holding it is skipped: the point lies on the
    // surface that sphere bounds (its surface included, within float rounding of eye-relative
    // metres), as is a leaf whose centre is behind the tangent plane.
    for (int i = 0; i < count && visible > 0.0;) {
        vec4 b = sphere_nodes[2 * i];
        vec2 link = sphere_nodes[2 * i + 1].xy;
        vec3 v = b.xyz - p;
        bool meets = sun_cone_meets(v, b.w, s, alpha);
        if (meets && link.y > 0.0) {
            float hold = b.w * 1.001 + 0.005;
            if (dot(v, v) > hold * hold && dot(v, n) > 0.0)
                visible *= 1.0 - ts_sphere_sun_cover(b.xyz, b.w, p, s, alpha);
        }
        i = meets ? i + 1 : int(link.x);
    }
    return visible;
}

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
    float cos_s = max(dot(n, frame.sun_direction.xyz), 0.0);
    float self_sun = cos_s > 0.0 && frame.aircraft_shadow.w > 0.0 ? self_shadow_sun(v_rel, n) : 1.0;
    vec3 e_sun = frame.sun_radiance.rgb * sun_solid_angle * cos_s * frame.aircraft_light.x * self_sun;
    float self_sky = frame.aircraft_shadow.w > 0.0 ? (gl_FrontFacing ? v_self_sky.x : v_self_sky.y) : 1.0;
    vec3 l = v_color / 3.14159265 * (max(e_sky, vec3(0.0)) * self_sky + e_sun);
    out_color = vec4(ts_display(l * frame.sun_radiance.w), 1.0);
}
