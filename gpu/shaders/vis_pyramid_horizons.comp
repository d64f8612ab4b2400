#version 450
// Pyramid horizons (core/visibility/pyramid_horizons.cpp): one invocation per receiver texel
// and azimuth marches the schedule's samples tau_k (at most 16 per octave of a grid's diagonal,
// so a few hundred loop iterations, far below llvmpipe's 65535 per invocation), each read from
// its pyramid level with the void-skipping bilinear blend, and keeps the steepest slope. The
// per-sample formulas are core/visibility/pyramid_shared.h and core/terrain/valid_bilinear_shared.h,
// the text the CPU compiles.
//
// Precision: the CPU works in double. Here a sample's position is the receiver's integer
// texel plus a float offset tau * step (a float alone holds a column near 3600 only to 2e-4
// texel), mapped to level l as the integer texel >> l plus a float remainder.
#extension GL_GOOGLE_include_directive : require
#define TS_GLSL 1
#include "core/terrain/valid_bilinear_shared.h"
#include "core/visibility/pyramid_shared.h"
layout(local_size_x = 8, local_size_y = 8) in;

#define PYRAMID_COARSE_ACCESS readonly
#include "gpu/visibility/vis_pyramid_levels.glsl"

struct Sample {
    float tau;  // texels from the receiver
    int level;
};
// Per grid row: the step in columns and rows per texel of tau for cos = sin = 1 (unit / dx,
// unit / dy) and unit = min(dx, dy) in metres (RowMetrics spacing).
struct RowStep {
    float udx, udy, unit, pad;
};
layout(std430, set = 0, binding = 7) readonly buffer Samples { Sample samples[]; };
layout(std430, set = 0, binding = 8) readonly buffer Rows { RowStep rows[]; };
layout(std430, set = 0, binding = 9) readonly buffer Directions { vec2 dirs[]; };  // cos, -sin
layout(std430, set = 0, binding = 10) writeonly buffer Horizons { float horizon[]; };  // [d][band texel]
// Every level in one buffer (LevelInfo.packed), when they fit: one load per corner instead of a
// choice of buffers, which llvmpipe runs as masked loads from each of them.
layout(constant_id = 2) const int kPacked = 0;
layout(std430, set = 0, binding = 11) readonly buffer Packed { float packed_levels[]; };

layout(push_constant) uniform Push {
    int col0, row0, band_w, band_h;  // the band of receivers on the grid
    int sample_count;
    float curvature;  // 1 / (2 R_eff) or 0
    float z_top;      // the grid's highest height
} p;

// Texel (c, r) of level l (w texels wide), described by info.
float level_texel(int l, LevelInfo info, int c, int r, int w) {
    uint i = uint(r) * uint(w) + uint(c);
    if (kPacked == 1) return packed_levels[info.packed + i];
    if (l == 0) return level_at(0, c, r);  // the parts of level 0
    return l == 1 ? level1[i] : levels2[info.offset + i];
}

// Level l's void-skipping bilinear height at level-0 texel-centre position (col + oc, row + orow),
// as TiledRaster::bilinear_valid at ((x + 0.5) / 2^l - 0.5, ...) clamped to the level.
float sample_level(int l, int col, int row, float oc, float orow) {
    LevelInfo info = levels[l];
    int w = info.width, h = info.height;
    float inv_scale = 1.0 / float(1 << l);  // a power of two: exact, as dividing by the scale
    int qc = col >> l, qr = row >> l;
    float xc = (float(col - (qc << l)) + 0.5 + oc) * inv_scale - 0.5;
    float xr = (float(row - (qr << l)) + 0.5 + orow) * inv_scale - 0.5;
    float fcl = floor(xc), frl = floor(xr);
    int c = qc + int(fcl), r = qr + int(frl);
    float fc = xc - fcl, fr = xr - frl;
    // Clamp to [0, n - 1], then the corner of valid_bilinear_corner (n - 2 with fraction 1 at the
    // last texel; 0 on a one-texel axis).
    if (c < 0) { c = 0; fc = 0.0; }
    if (c > w - 1 || (c == w - 1 && fc > 0.0)) { c = w - 1; fc = 0.0; }
    if (r < 0) { r = 0; fr = 0.0; }
    if (r > h - 1 || (r == h - 1 && fr > 0.0)) { r = h - 1; fr = 0.0; }
    if (c >= w - 1 && w > 1) { c = w - 2; fc += 1.0; }
    if (r >= h - 1 && h > 1) { r = h - 2; fr += 1.0; }
    int c1 = min(c + 1, w - 1), r1 = min(r + 1, h - 1);
    return ts_blend_valid_corners(level_texel(l, info, c, r, w), level_texel(l, info, c1, r, w),
                                  level_texel(l, info, c, r1, w), level_texel(l, info, c1, r1, w), fc, fr);
}

void main() {
    int lc = int(gl_GlobalInvocationID.x), lr = int(gl_GlobalInvocationID.y), d = int(gl_GlobalInvocationID.z);
    if (lc >= p.band_w || lr >= p.band_h) return;
    int col = p.col0 + lc, row = p.row0 + lr;
    uint out_index = uint(d) * uint(p.band_w) * uint(p.band_h) + uint(lr) * uint(p.band_w) + uint(lc);
    float zr = level_at(0, col, row);
    if (isnan(zr)) {
        horizon[out_index] = uintBitsToFloat(0x7fc00000u);
        return;
    }
    float wmax = float(levels[0].width - 1), hmax = float(levels[0].height - 1);
    RowStep rs = rows[row];
    vec2 dir = dirs[d];
    float step_c = dir.x * rs.udx, step_r = dir.y * rs.udy;
    // The grid's edges as offsets from the receiver, with the CPU's 1e-7 texel slack for edge
    // rows (precise: fast-math must not fold the slack away).
    precise float lo_c = -float(col) - 1e-7, lo_r = -float(row) - 1e-7;
    precise float hi_c = (wmax - float(col)) + 1e-7, hi_r = (hmax - float(row)) + 1e-7;
    float best = uintBitsToFloat(0xff800000u);  // -infinity: no surface met
    for (int k = 0; k < p.sample_count; ++k) {
        Sample smp = samples[k];
        float oc = smp.tau * step_c, orow = smp.tau * step_r;
        // Off the grid: the march ends.
        if (oc < lo_c || orow < lo_r || oc > hi_c || orow > hi_r) break;
        float s = smp.tau * rs.unit;
        if (ts_pyramid_slope(p.z_top, zr, s, p.curvature) <= best) break;
        float z = sample_level(smp.level, col, row, oc, orow);
        if (isnan(z)) continue;
        best = max(best, ts_pyramid_slope(z, zr, s, p.curvature));
    }
    horizon[out_index] = isinf(best) ? 0.0 : atan(best);
}
