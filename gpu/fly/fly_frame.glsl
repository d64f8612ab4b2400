// The flythrough's resources as every fly_* shader sees them (gpu/fly/fly_renderer.cpp fills
// them; FrameUniforms there mirrors the Frame block field by field).
#ifndef TS_GLSL
#define TS_GLSL 1
#endif
#include "core/raster/display_shared.h"

layout(std430, set = 0, binding = 0) readonly buffer Frame {
    mat4 view_projection;  // eye-relative metres -> clip (reversed Z, infinite far)
    vec4 eye;              // xyz: the eye in the grid frame's metres, w: the sun's angular radius (rad)
    vec4 grid;             // width, height, centre column, haze distance (m; 0 = no haze)
    vec4 sun_direction;    // xyz unit ENU, w: cos of the disc's angular radius
    vec4 sun_radiance;     // rgb radiance inside the disc, w: exposure scale
    vec4 camera_right;     // xyz, w: tan(horizontal fov / 2)
    vec4 camera_up;        // xyz, w: tan(vertical fov / 2)
    vec4 camera_forward;   // xyz
    vec4 sky_table;        // azimuth count, elevation count, lowest elevation (rad), highest (rad)
    vec4 sky_sh[16];       // rgb: the sky the terrain lets reach the aircraft, order-4 SH
                           // (core/render/point_terrain_light.hpp: exp(V_log) * L_sky)
    vec4 aircraft_light;   // x: the visible fraction of the sun's disc at the aircraft
    vec4 aircraft_bound;   // the aircraft's spheres' bound: eye-relative centre, radius (0: no shadows)
    vec4 aircraft_shadow;  // node count, sky footprint radius (m), sun angular radius (rad), self-shadow (1)
    vec4 aircraft_sky;     // x: far share of the bound's sky cover, y: bound cover above which each sphere counts
    // The overview at the start of Heights, Radiance and TerrainSun (gpu/fly/fly_patch.glsl):
    // every overview.z-th level-0 texel, overview.xy of them; a DEM in memory has them all.
    vec4 overview;         // width, height, level-0 texels per texel, CDLOD levels read from tiles
} frame;
layout(std430, set = 0, binding = 1) readonly buffer Heights { float heights[]; };     // overview, then atlas slots
layout(std430, set = 0, binding = 2) readonly buffer Rows { vec2 rows[]; };            // dx_m, north_m
layout(std430, set = 0, binding = 3) readonly buffer Radiance { uvec2 radiance[]; };   // rgb fp16 per texel
layout(std430, set = 0, binding = 4) readonly buffer Sky { vec4 sky[]; };              // [elevation][azimuth]
// The aircraft: 3 vertices per triangle, each position (xyz, model metres), normal, colour.
layout(std430, set = 0, binding = 5) readonly buffer Aircraft { vec4 aircraft[]; };
// Radiance holds each texel's radiance less the sun's diffuse term; this the term's parts
// (core/render/texel_sun_split.hpp, core/fly/radiance_pack.hpp): packHalf2x16 of (a.r, a.g),
// (a.b, open-sky fraction), (n.x, n.y), (h - e, 0), with a = albedo E_sun / pi, n the texel's
// unit normal (east, north; up implied), h - e its horizon in the sun's azimuth above the sun.
layout(std430, set = 0, binding = 6) readonly buffer TerrainSun { uvec4 terrain_sun[]; };
// The aircraft's sphere hierarchy this frame, depth-first (core/blockers/sphere_hierarchy.hpp,
// FlatSphereNode), two vec4 a node: its bound (eye-relative centre, radius; metres), then (the
// index past its subtree, 1 for a leaf, the share of its bound's sky cover its leaves keep from
// afar). A walk goes on to i + 1 from a node it accepts and to the skip index from one it
// refuses.
layout(std430, set = 0, binding = 7) readonly buffer Spheres { vec4 sphere_nodes[]; };

// Whether the cone of directions within `sun_radius` of the sun seen from a receiver meets a
// sphere `v` (centre minus receiver) away: the sphere then hides part of the disc. A cheap
// conservative test (the exact cover is ts_sphere_sun_cover) for skipping spheres.
bool sun_cone_meets(vec3 v, float radius, vec3 sun, float sun_radius) {
    float along = dot(v, sun);
    if (along < -radius) return false;
    float reach = max(along, 0.0) * sun_radius * 1.001 + radius * 1.001;
    return dot(v, v) - along * along < reach * reach;
}

// Sky radiance (the sun's disc apart) in a direction, bilinear in azimuth (wrapping) and
// elevation (clamped); azimuth counter-clockwise from east as in the rest of terrashade.
vec3 sky_radiance(vec3 dir) {
    int na = int(frame.sky_table.x), ne = int(frame.sky_table.y);
    float az = atan(dir.y, dir.x);
    if (az < 0.0) az += 6.283185307179586;
    float el = asin(clamp(dir.z, -1.0, 1.0));
    float u = az / 6.283185307179586 * float(na);
    float v = (el - frame.sky_table.z) / (frame.sky_table.w - frame.sky_table.z) * float(ne - 1);
    v = clamp(v, 0.0, float(ne - 1));
    int a0 = int(floor(u)) % na, a1 = (a0 + 1) % na;
    int e0 = min(int(floor(v)), ne - 2), e1 = e0 + 1;
    float fu = fract(u), fv = v - float(e0);
    vec3 top = mix(sky[e0 * na + a0].rgb, sky[e0 * na + a1].rgb, fu);
    vec3 bottom = mix(sky[e1 * na + a0].rgb, sky[e1 * na + a1].rgb, fu);
    return mix(top, bottom, fv);
}
