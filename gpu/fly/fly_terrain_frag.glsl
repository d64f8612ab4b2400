// The terrain's fragment shader, compiled twice (gpu/shaders/fly_terrain.frag and
// fly_terrain_fade.frag): with TS_FLY_FADE 1 it also blends the overview's radiance across a
// detail tile's fade band. Two pipelines rather than a branch: a CPU Vulkan device runs a
// branch's body whatever its condition, so every patch would pay the overview's extra reads.
// The terrain's colour: the per-texel radiance of this sun and sky (the CPU's fused diffuse
// pass over the cached transfer vectors, core/render/diffuse_shading.hpp) less the sun's
// diffuse term, bilinear, and that term per fragment (core/render/texel_sun_split.hpp): the
// texels' a = albedo E_sun / pi, normals and horizons in the sun's azimuth interpolated, the
// disc's visible fraction above the interpolated horizon (core/visibility/sun_disc_shared.h,
// the text the CPU compiles), so a shadow's edge falls inside the texels where the horizon
// crosses the sun instead of on a texel-wide ramp. Then less what the aircraft's spheres hide
// of the sun's disc and of the sky (core/blockers/sphere_occlusion_shared.h) inside its
// footprint, aerial perspective towards the sky's horizon radiance in the ray's azimuth (as
// core/render/perspective_view.hpp; from the vertex shader), exposure and the display curve.
#define TS_GLSL 1
#include "core/blockers/sphere_occlusion_shared.h"
#include "core/visibility/sun_disc_shared.h"
#include "gpu/fly/fly_frame.glsl"
#include "gpu/fly/fly_patch.glsl"

layout(location = 0) in vec2 v_texel;
layout(location = 1) in vec3 v_haze;
layout(location = 2) in float v_transmittance;
layout(location = 3) in vec3 v_rel;
layout(location = 4) in float v_overview;
layout(location = 0) out vec4 out_color;

vec3 unpack_rgb(uvec2 p) { return vec3(unpackHalf2x16(p.x), unpackHalf2x16(p.y).x); }

vec3 rest_at(TerrainCorners c) {
    ivec4 i = c.index;
    return mix(mix(unpack_rgb(radiance[i.x]), unpack_rgb(radiance[i.y]), c.f.x),
               mix(unpack_rgb(radiance[i.z]), unpack_rgb(radiance[i.w]), c.f.x), c.f.y);
}

// The sun's term's parts at a fragment: a (rgb) and the open-sky fraction; the normal's east
// and north components and h - e.
struct SunLight {
    vec4 a_open;
    vec3 n_h;
};

vec4 unpack_a_open(uvec4 p) { return vec4(unpackHalf2x16(p.x), unpackHalf2x16(p.y)); }
vec3 unpack_n_h(uvec4 p) { return vec3(unpackHalf2x16(p.z), unpackHalf2x16(p.w).x); }

SunLight sun_light_at(TerrainCorners c) {
    ivec4 i = c.index;
    uvec4 p0 = terrain_sun[i.x], p1 = terrain_sun[i.y], p2 = terrain_sun[i.z], p3 = terrain_sun[i.w];
    SunLight l;
    l.a_open = mix(mix(unpack_a_open(p0), unpack_a_open(p1), c.f.x), mix(unpack_a_open(p2), unpack_a_open(p3), c.f.x), c.f.y);
    l.n_h = mix(mix(unpack_n_h(p0), unpack_n_h(p1), c.f.x), mix(unpack_n_h(p2), unpack_n_h(p3), c.f.x), c.f.y);
    return l;
}

SunLight mix_sun_light(SunLight a, SunLight b, float t) {
    return SunLight(mix(a.a_open, b.a_open, t), mix(a.n_h, b.n_h, t));
}

// The sun's diffuse term: a max(0, n.s) F((e - h) / r), the normal's up component from its
// interpolated east and north ones (a unit normal's, so the slope is what is blended).
vec3 sun_term(SunLight l) {
    vec2 en = l.n_h.xy;
    vec3 n = normalize(vec3(en, sqrt(max(1.0 - dot(en, en), 0.0))));
    float r = max(frame.eye.w, 1e-6);
    return l.a_open.rgb * max(dot(n, frame.sun_direction.xyz), 0.0) * ts_sun_disc_fraction(-l.n_h.z / r);
}

// The aircraft's shadows at this fragment: the radiance `l` (of which `l_sun` is the sun's part)
// with the sun's disc fraction its spheres hide taken from the sun's part, and from the rest the
// share of the sky they hide of what the terrain leaves open (ts_open_sky_share: in a valley
// the aircraft hides more of a smaller sky). Only receivers in the bound's sun cone or sky
// footprint loop over the spheres.
vec3 aircraft_shadowed(vec3 l, vec3 l_sun, float open_sky, vec3 p, vec3 n) {
    vec3 c = frame.aircraft_bound.xyz;
    float r = frame.aircraft_bound.w;
    vec3 s = frame.sun_direction.xyz;
    float alpha = frame.aircraft_shadow.z;
    vec3 v = c - p;
    float footprint = frame.aircraft_shadow.y;
    bool sun = sun_cone_meets(v, r, s, alpha);
    float bound_sky = dot(v, v) < footprint * footprint ? ts_sphere_sky_cover(c, r, p, n) : 0.0;
    if (!sun && bound_sky <= 0.0) return l;
    sun = sun && (l_sun.r + l_sun.g + l_sun.b) > 0.0;
    // Near the bound its parts' covers combine one by one; farther the bound's cover times the
    // share its spheres keep from afar (one evaluation). The same rule down the hierarchy: a
    // node whose cover is at most the detail threshold counts as its cover times its own far
    // share, and its subtree is not opened for the sky.
    float detail = frame.aircraft_sky.y;
    bool sky_detail = bound_sky > detail;
    float sky_cover = bound_sky * frame.aircraft_sky.x;
    if (!sun && !sky_detail) return l - max(l - l_sun, vec3(0.0)) * ts_open_sky_share(sky_cover, open_sky);
    float sun_visible = 1.0, sky_product = 1.0;
    int count = int(frame.aircraft_shadow.x);
    // The hierarchy walk: the sun cone prunes subtrees; the sky opens the nodes whose caps are
    // large from here. `sky_done` is the index past the last subtree the sky has counted.
    int sky_done = sky_detail ? 0 : count;
    for (int i = 0; i < count;) {
        vec4 b = sphere_nodes[2 * i];
        vec3 link = sphere_nodes[2 * i + 1].xyz;
        bool leaf = link.y > 0.0;
        bool in_sun = sun && sun_visible > 0.0 && sun_cone_meets(b.xyz - p, b.w, s, alpha);
        if (leaf && in_sun) sun_visible *= 1.0 - ts_sphere_sun_cover(b.xyz, b.w, p, s, alpha);
        bool open_sky = false;
        if (i >= sky_done) {
            float c = ts_sphere_sky_cover(b.xyz, b.w, p, n);
            if (leaf || c <= detail) {
                sky_product = ts_sky_cover_step(sky_product, leaf ? c : c * link.z, bound_sky);
                sky_done = int(link.x);
            } else {
                open_sky = true;
            }
        }
        i = in_sun || open_sky ? i + 1 : int(link.x);
    }
    if (sky_detail) sky_cover = ts_sky_cover_union(sky_product, bound_sky);
    vec3 l_sky = max(l - l_sun, vec3(0.0));
    return l - l_sun * (1.0 - sun_visible) - l_sky * ts_open_sky_share(sky_cover, open_sky);
}

void main() {
    vec2 t = clamp(v_texel, vec2(0.0), frame.grid.xy - 1.0);
    // The patch's block, and in a tile's fade band the overview's.
    TerrainCorners corners = patch_corners(t);
    vec3 rest = rest_at(corners);
    SunLight sun = sun_light_at(corners);
    float fade = v_overview;
#if TS_FLY_FADE
    TerrainCorners overview = overview_corners(t);
    rest = mix(rest, rest_at(overview), fade);
    sun = mix_sun_light(sun, sun_light_at(overview), fade);
#endif
    vec3 l_sun = sun_term(sun);
    vec3 l = rest + l_sun;
    // The drawn triangle's normal (derivatives are taken where every fragment still runs).
    vec3 n = cross(dFdx(v_rel), dFdy(v_rel));
    n = dot(n, n) > 0.0 ? normalize(n) : vec3(0.0, 0.0, 1.0);
    if (n.z < 0.0) n = -n;
    if (frame.aircraft_bound.w > 0.0) l = aircraft_shadowed(l, l_sun, sun.a_open.a, v_rel, n);
    l = l * v_transmittance + v_haze * (1.0 - v_transmittance);
    // The display transform of every 8-bit picture (core/raster/display_shared.h).
    out_color = vec4(ts_display(l * frame.sun_radiance.w), 1.0);
}
