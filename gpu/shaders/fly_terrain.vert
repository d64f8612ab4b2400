#version 450
// The flythrough's terrain: one CDLOD patch (core/fly/cdlod_tree.hpp) per draw, its vertex
// grid from gl_VertexIndex (index = i + j (N + 1)), the morph and the curvature drop from
// core/fly/cdlod_shared.h (the text the CPU selection and its tests compile too).
#extension GL_GOOGLE_include_directive : require
#define TS_GLSL 1
#include "core/fly/cdlod_shared.h"
#include "gpu/fly/fly_frame.glsl"
#include "gpu/fly/fly_patch.glsl"

layout(location = 0) out vec2 v_texel;  // level-0 texel-centre coordinates
layout(location = 1) out vec3 v_haze;      // the sky's horizon radiance in this azimuth
layout(location = 2) out float v_transmittance;
layout(location = 3) out vec3 v_rel;    // eye-relative grid-frame metres, before the curvature drop
// The overview's share of the fragment's radiance: a tile's coarsest level fades to the
// overview's across its morph band, where its geometry becomes the overview's; 0 elsewhere.
layout(location = 4) out float v_overview;

float height_at(vec2 t) {
    TerrainCorners c = patch_corners(t);
    return bilinear(vec4(heights[c.index.x], heights[c.index.y], heights[c.index.z], heights[c.index.w]), c.f);
}

vec3 grid_point(vec2 t) {
    int h = int(frame.grid.y);
    int r0 = min(int(floor(t.y)), h - 2);
    vec2 row = mix(rows[r0], rows[r0 + 1], t.y - float(r0));
    return vec3((t.x - frame.grid.z) * row.x, row.y, height_at(t));
}

void main() {
    uint n1 = patch_.quads + 1u;
    float i = float(uint(gl_VertexIndex) % n1), j = float(uint(gl_VertexIndex) / n1);
    vec2 last = frame.grid.xy - 1.0;
    vec2 t = min(vec2(patch_.col0 + i * patch_.spacing, patch_.row0 + j * patch_.spacing), last);
    float d = distance(grid_point(t), frame.eye.xyz);
    float m = ts_cdlod_morph_factor(d, patch_.morph_start_m, patch_.morph_end_m);
    vec2 tm = min(vec2(patch_.col0 + ts_cdlod_morph_index(i, m) * patch_.spacing,
                       patch_.row0 + ts_cdlod_morph_index(j, m) * patch_.spacing), last);
    vec3 rel = grid_point(tm) - frame.eye.xyz;
    v_rel = rel;
    rel.z -= ts_curvature_drop(dot(rel.xy, rel.xy));
    gl_Position = frame.view_projection * vec4(rel, 1.0);
    v_texel = tm;
    v_overview = float(patch_.fade) * m;
    // Aerial perspective per vertex (it varies slowly over a triangle; the fragment shader
    // would pay the sky lookup for every pixel).
    float dist = length(rel);
    v_haze = sky_radiance(normalize(vec3(rel.xy, 0.0) + vec3(1e-6, 0.0, 0.0)));
    v_transmittance = frame.grid.w > 0.0 ? exp(-dist / frame.grid.w) : 1.0;
}
