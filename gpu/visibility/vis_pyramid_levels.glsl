// The mean height pyramid on the device, for the vis_pyramid_*.comp shaders. Define
// PYRAMID_COARSE_ACCESS (readonly or empty: the level builder writes the coarse levels)
// before including.
//
// Storage: level 0 is the heights, split by rows into kHeightParts buffers of kRowsPerPart
// rows (bindings 0..3, part 0 bound again where a part does not exist: grids above
// maxStorageBufferRange). Level 1 has a buffer of its own (binding 4, a quarter of level 0);
// levels 2.. are packed one after the other in binding 5 (a third of level 1 in all). Each
// level is row-major width x height; binding 6 says where each level lives.
layout(constant_id = 0) const int kHeightParts = 1;
layout(constant_id = 1) const int kRowsPerPart = 1073741824;

layout(std430, set = 0, binding = 0) readonly buffer Heights0 { float z0[]; };
layout(std430, set = 0, binding = 1) readonly buffer Heights1 { float z1[]; };
layout(std430, set = 0, binding = 2) readonly buffer Heights2 { float z2[]; };
layout(std430, set = 0, binding = 3) readonly buffer Heights3 { float z3[]; };
layout(std430, set = 0, binding = 4) PYRAMID_COARSE_ACCESS buffer Level1 { float level1[]; };
layout(std430, set = 0, binding = 5) PYRAMID_COARSE_ACCESS buffer Levels2 { float levels2[]; };

// PyramidLevelInfo of gpu_pyramid.cpp.
struct LevelInfo {
    int width, height;
    uint offset;  // of texel (0, 0) in its buffer, in floats (levels >= 2: in levels2)
    uint packed;  // of texel (0, 0) in the packed copy of every level (gpu_pyramid.cpp), if any
};
layout(std430, set = 0, binding = 6) readonly buffer Levels { LevelInfo levels[]; };

// Texel (c, r) of level l, 0 <= c < width, 0 <= r < height.
float level_at(int l, int c, int r) {
    if (l == 0) {
        int w = levels[0].width;
        if (kHeightParts == 1) return z0[r * w + c];
        int part = r / kRowsPerPart;
        int i = (r - part * kRowsPerPart) * w + c;
        if (part == 0) return z0[i];
        if (part == 1) return z1[i];
        if (part == 2) return z2[i];
        return z3[i];
    }
    uint i = uint(r) * uint(levels[l].width) + uint(c);
    if (l == 1) return level1[i];
    return levels2[levels[l].offset + i];
}
