// One CDLOD patch's push constants (gpu/fly/fly_renderer.cpp PatchPush), for the terrain's
// vertex and fragment shaders, and where its heights and radiance are read: a detail tile's slot
// (slot >= 0, the tile's first sample at level-0 texel tile_origin) or the overview (slot -1).
layout(push_constant) uniform Patch {
    float col0, row0, spacing, morph_start_m, morph_end_m;
    uint quads;
    int slot;
    int level;
    vec2 tile_origin;
} patch_;

// Bilinear corners of level-0 position t (texel-centre coordinates) in the patch's source: the
// four indices into its buffers and the weights.
struct TerrainCorners {
    ivec4 index;
    vec2 f;
};

TerrainCorners overview_corners(vec2 t) {
    int w = int(frame.overview.x), h = int(frame.overview.y);
    vec2 u = clamp(t / frame.overview.z, vec2(0.0), vec2(w - 1, h - 1));
    int c0 = min(int(floor(u.x)), w - 2), r0 = min(int(floor(u.y)), h - 2);
    int i = r0 * w + c0;
    return TerrainCorners(ivec4(i, i + 1, i + w, i + w + 1), u - vec2(c0, r0));
}

TerrainCorners tile_corners(vec2 t) {
    int stride = int(frame.atlas.x);
    // An edge tile holds fewer samples: up to the grid's last texel.
    ivec2 samples = min(ivec2(stride - 1), ivec2(frame.grid.xy) - 1 - ivec2(patch_.tile_origin)) + 1;
    vec2 u = clamp(t - patch_.tile_origin, vec2(0.0), vec2(samples - 1));
    int c0 = min(int(floor(u.x)), samples.x - 2), r0 = min(int(floor(u.y)), samples.y - 2);
    int i = patch_.slot * stride * stride + r0 * stride + c0;
    return TerrainCorners(ivec4(i, i + 1, i + stride, i + stride + 1), u - vec2(c0, r0));
}

float bilinear(vec4 v, vec2 f) { return mix(mix(v.x, v.y, f.x), mix(v.z, v.w, f.x), f.y); }
