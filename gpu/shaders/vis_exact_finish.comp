#version 450
// Exact horizons, per receiver texel and one azimuth (the end of the CPU's exact_horizons):
// the tent-weighted mean of the far-field slopes of the sweep lines passing within one line
// spacing of the texel (the CPU splats them; here each texel gathers the same lines with the
// same weights), where the lines with a far field carry at least as much of the weight as those
// without (exact_azimuth.hpp, has_far_field), then the receiver's own near field marched from
// the texel centre in 1/4-texel steps, and the elevation angle. NaN for void receivers, 0 where
// nothing lies that way.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 8, local_size_y = 8) in;

struct RowInfo { float dx, dy, g_hi, near_steps, g_lo, dg, pad0, pad1; };
struct FarEntry { float slope; float frac; int whole; int pad; };  // slope NaN: no sample; -inf: no far field

layout(std430, set = 0, binding = 0) readonly buffer Heights { float z[]; };
layout(std430, set = 0, binding = 1) readonly buffer Rows { RowInfo rows[]; };
layout(std430, set = 0, binding = 2) readonly buffer Far { FarEntry far[]; };
layout(std430, set = 0, binding = 3) buffer Horizons { float horizon[]; };  // [d][row][col] of the window
// The highest height of the 3 x 3 blocks of kTopTile x kTopTile texels around each block
// (host-made, as the CPU's ExactAzimuthSweep::near_top): the near field's exact early exit.
layout(std430, set = 0, binding = 7) readonly buffer BlockTop { float block_top[]; };  // [tile row][tile col]
const int kTopTile = 16;

layout(push_constant) uniform Push {
    int width, height;
    int col0, row0, win_w, win_h;
    int columns;
    int n_min;
    int total_lines;
    int d;
    float cs, sn, h, curvature, z_top, row_spacing;
    int tiles_x;  // blocks across block_top; 0: no block tops (near field too long), use z_top
} p;

#define GRID_W p.width
#define GRID_H p.height
#define HEIGHTS_BINDING_1 4
#define HEIGHTS_BINDING_2 5
#define HEIGHTS_BINDING_3 6
#include "gpu/visibility/vis_surface.glsl"

const float kMarchStepTexels = 0.25;

void main() {
    int lc = int(gl_GlobalInvocationID.x), lr = int(gl_GlobalInvocationID.y);
    if (lc >= p.win_w || lr >= p.win_h) return;
    int col = p.col0 + lc, row = p.row0 + lr;
    uint out_index = uint(p.d) * uint(p.win_w * p.win_h) + uint(lr * p.win_w + lc);
    float z0 = height_at(col, row);
    if (isnan(z0)) {
        horizon[out_index] = kNaN;
        return;
    }

    // Far field: the lines whose invariant col*sn + G*cs lies near this texel's.
    float center = (float(col) * p.sn + rows[row].g_hi * p.cs) / p.h;
    int along_len = p.columns == 1 ? p.win_w : p.win_h;
    int along = p.columns == 1 ? lc : lr;
    int t = p.columns == 1 ? row : col;
    float sum = 0.0, wsum = 0.0, empty = 0.0;
    for (int n = int(floor(center)) - 2; n <= int(ceil(center)) + 2; ++n) {
        int line = n - p.n_min;
        if (line < 0 || line >= p.total_lines) continue;
        FarEntry e = far[uint(line) * uint(along_len) + uint(along)];
        if (isnan(e.slope)) continue;
        float spacing = p.columns == 1 ? p.h / abs(p.cs) / rho_at(e.whole, e.frac) : p.row_spacing;
        float w = 1.0 - abs(float(e.whole - t) + e.frac) / spacing;
        if (w <= 0.0) continue;
        if (e.slope == kNone) {
            empty += w;
            continue;
        }
        sum += w * e.slope;
        wsum += w;
    }
    float best = wsum > 0.0 && wsum >= empty ? sum / wsum : kNone;

    // Near field, marched as the reference marches it.
    RowInfo rm = rows[row];
    float ds = kMarchStepTexels * min(rm.dx, rm.dy);
    float dc = p.cs * ds / rm.dx, dr = -p.sn * ds / rm.dy;
    int steps = int(rm.near_steps);
    float wmax = float(p.width - 1), hmax = float(p.height - 1);
    float z_top = p.tiles_x > 0 ? block_top[(row / kTopTile) * p.tiles_x + col / kTopTile] : p.z_top;
    for (int k = 1; k <= steps; ++k) {
        float c = float(col) + float(k) * dc, r = float(row) + float(k) * dr, sk = float(k) * ds;
        if (c < -1e-5 || r < -1e-5 || c > wmax + 1e-5 || r > hmax + 1e-5) break;
        if ((z_top - z0) / sk - p.curvature * sk <= best) break;  // exact early exit
        // Offsets from the texel itself keep the position exact (clamped onto the grid).
        float oc = clamp(float(k) * dc, -float(col), wmax - float(col));
        float orow = clamp(float(k) * dr, -float(row), hmax - float(row));
        float zz = bilinear_valid_at(col, row, oc, orow);
        if (!isnan(zz)) best = max(best, (zz - z0) / sk - p.curvature * sk);
    }
    horizon[out_index] = best == kNone ? 0.0 : atan(best);
}
