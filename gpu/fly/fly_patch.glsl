// One CDLOD patch's push constants (gpu/fly/fly_renderer.cpp PatchPush), for the terrain's
// vertex and fragment shaders, and where its heights and radiance are read. Heights, Radiance
// and TerrainSun hold the overview's texels (a DEM in memory: all of them) and then the detail
// tiles' atlas slots; a patch reads a dims.x x dims.y block of rows `stride` from `base`, its
// texel (0, 0) at level-0 position `origin`, 1 / inv_scale level-0 texels apart. One code path for
// either source: a CPU Vulkan device runs both sides of a branch.
layout(push_constant) uniform Patch {
    float col0, row0, spacing, morph_start_m, morph_end_m;
    uint quads;
    int base, stride;
    vec2 origin;
    float inv_scale;
    int fade;  // 1: a tile's coarsest level, whose radiance fades to the overview's in its morph band
    ivec2 dims;
} patch_;

// Bilinear corners of level-0 position t (texel-centre coordinates): four buffer indices and
// the weights.
struct TerrainCorners {
    ivec4 index;
    vec2 f;
};

TerrainCorners block_corners(vec2 t, int base, int stride, vec2 origin, float inv_scale, ivec2 dims) {
    vec2 u = clamp((t - origin) * inv_scale, vec2(0.0), vec2(dims - 1));
    ivec2 c = min(ivec2(floor(u)), dims - 2);
    int i = base + c.y * stride + c.x;
    return TerrainCorners(ivec4(i, i + 1, i + stride, i + stride + 1), u - vec2(c));
}

TerrainCorners patch_corners(vec2 t) {
    return block_corners(t, patch_.base, patch_.stride, patch_.origin, patch_.inv_scale, patch_.dims);
}

TerrainCorners overview_corners(vec2 t) {
    ivec2 dims = ivec2(frame.overview.xy);
    return block_corners(t, 0, dims.x, vec2(0.0), 1.0 / frame.overview.z, dims);
}

float bilinear(vec4 v, vec2 f) { return mix(mix(v.x, v.y, f.x), mix(v.z, v.w, f.x), f.y); }
