// GLSL twins of the CPU horizon code's grid helpers (core/visibility/surface_sampling.hpp and
// row_metrics.hpp), for the vis_*.comp shaders. Included after the shader declares
//   struct RowInfo { float dx, dy, g_hi, near_steps, g_lo, dg, pad0, pad1; };
//   layout(std430, binding = 0) readonly buffer Heights { float z[]; };
//   layout(std430, binding = 1) readonly buffer Rows { RowInfo rows[]; };
// and defines GRID_W / GRID_H (the grid's size, ints) and HEIGHTS_BINDING_1..3 (bindings of the
// other height parts, see height_at) before including.
// Same rules as the CPU: a void (NaN) neither blocks nor receives; bilinear over valid corners
// with renormalised weights; rows' east-west spacing already floored (RowMetrics::kMinAspect).
//
// Positions on the grid are an integer texel plus a float offset: a float alone holds a row
// near 1000 only to 6e-5, which moved steep horizons by 1e-4 rad on a 1201 x 1201 tile.

#define kNaN uintBitsToFloat(0x7fc00000u)
#define kNone uintBitsToFloat(0xff800000u)  // -infinity: no blocker

// surface_sampling.hpp's lerp_valid: a valid height with weight only up to rounding is no surface.
float lerp_valid(float a, float b, float t) {
    bool va = !isnan(a), vb = !isnan(b);
    if (va && vb) return a + t * (b - a);
    if (va && 1.0 - t > 1e-6) return a;
    if (vb && t > 1e-6) return b;
    return kNaN;
}

// Heights of the whole grid, row-major, split by rows into kHeightParts storage buffers of
// kRowsPerPart rows each (so a grid larger than maxStorageBufferRange still fits): part 0 is
// `z` at binding 0, parts 1..3 at HEIGHTS_BINDING_1..3 (the shader defines them; the host binds
// part 0 again where a part does not exist). Specialization constants: with one part the
// compiler drops the selection.
layout(constant_id = 0) const int kHeightParts = 1;
layout(constant_id = 1) const int kRowsPerPart = 1073741824;
layout(std430, set = 0, binding = HEIGHTS_BINDING_1) readonly buffer Heights1 { float z1[]; };
layout(std430, set = 0, binding = HEIGHTS_BINDING_2) readonly buffer Heights2 { float z2[]; };
layout(std430, set = 0, binding = HEIGHTS_BINDING_3) readonly buffer Heights3 { float z3[]; };

float height_at(int c, int r) {
    if (kHeightParts == 1) return z[r * GRID_W + c];
    int part = r / kRowsPerPart;
    int i = (r - part * kRowsPerPart) * GRID_W + c;
    if (part == 0) return z[i];
    if (part == 1) return z1[i];
    if (part == 2) return z2[i];
    return z3[i];
}

// surface_sampling.hpp's bilinear_valid at (base_col + off_col, base_row + off_row).
float bilinear_valid_at(int base_col, int base_row, float off_col, float off_row) {
    int w = GRID_W, h = GRID_H;
    float fcol = floor(off_col), frow = floor(off_row);
    int c0 = base_col + int(fcol), r0 = base_row + int(frow);
    float fc = off_col - fcol, fr = off_row - frow;
    if (c0 >= w - 1) { fc += float(c0 - (w > 1 ? w - 2 : 0)); c0 = w > 1 ? w - 2 : 0; }
    if (r0 >= h - 1) { fr += float(r0 - (h > 1 ? h - 2 : 0)); r0 = h > 1 ? h - 2 : 0; }
    int c1 = w > 1 ? c0 + 1 : c0, r1 = h > 1 ? r0 + 1 : r0;
    float z00 = height_at(c0, r0), z10 = height_at(c1, r0);
    float z01 = height_at(c0, r1), z11 = height_at(c1, r1);
    if (!isnan(z00) && !isnan(z10) && !isnan(z01) && !isnan(z11)) {
        float top = z00 + fc * (z10 - z00), bottom = z01 + fc * (z11 - z01);
        return top + fr * (bottom - top);
    }
    float w00 = (1.0 - fc) * (1.0 - fr), w10 = fc * (1.0 - fr), w01 = (1.0 - fc) * fr, w11 = fc * fr;
    float sum = 0.0, wsum = 0.0;
    if (!isnan(z00)) { sum += w00 * z00; wsum += w00; }
    if (!isnan(z10)) { sum += w10 * z10; wsum += w10; }
    if (!isnan(z01)) { sum += w01 * z01; wsum += w01; }
    if (!isnan(z11)) { sum += w11 * z11; wsum += w11; }
    return wsum > 1e-6 ? sum / wsum : kNaN;
}

// A line sample: linear between the two texels it passes between, at integer column c and
// row (whole + frac), or at integer row r and column (whole + frac).
float sample_column(int c, int whole, float frac) {
    int r0 = min(whole, GRID_H - 1);
    return r0 + 1 < GRID_H ? lerp_valid(height_at(c, r0), height_at(c, r0 + 1), frac) : height_at(c, r0);
}
float sample_row(int r, int whole, float frac) {
    int c0 = min(whole, GRID_W - 1);
    return c0 + 1 < GRID_W ? lerp_valid(height_at(c0, r), height_at(c0 + 1, r), frac) : height_at(c0, r);
}

// Per-row spacing, linear between rows and clamped at the ends (RowMetrics::lerp_rows).
vec2 spacing_at(int whole, float frac) {
    if (whole < 0 || (whole == 0 && frac <= 0.0)) return vec2(rows[0].dx, rows[0].dy);
    if (whole >= GRID_H - 1) return vec2(rows[GRID_H - 1].dx, rows[GRID_H - 1].dy);
    return mix(vec2(rows[whole].dx, rows[whole].dy), vec2(rows[whole + 1].dx, rows[whole + 1].dy), frac);
}
float rho_at(int whole, float frac) { vec2 s = spacing_at(whole, frac); return s.y / s.x; }

// ---- double-float arithmetic: a value is hi + lo, two floats (about 48 bits) ----
vec2 quick_two_sum(float a, float b) {
    precise float s = a + b;
    precise float e = b - (s - a);
    return vec2(s, e);
}
vec2 two_sum(float a, float b) {
    precise float s = a + b;
    precise float bb = s - a;
    precise float e = (a - (s - bb)) + (b - bb);
    return vec2(s, e);
}
vec2 split(float a) {  // Veltkamp: hi keeps 12 bits, so products of halves are exact
    precise float c = 4097.0 * a;
    precise float hi = c - (c - a);
    precise float lo = a - hi;
    return vec2(hi, lo);
}
vec2 two_prod(float a, float b) {
    precise float prod = a * b;
    vec2 sa = split(a), sb = split(b);
    precise float e = ((sa.x * sb.x - prod) + sa.x * sb.y + sa.y * sb.x) + sa.y * sb.y;
    return vec2(prod, e);
}
vec2 df_add(vec2 a, vec2 b) {
    vec2 s = two_sum(a.x, b.x);
    precise float lo = s.y + (a.y + b.y);
    return quick_two_sum(s.x, lo);
}
vec2 df_mul(vec2 a, vec2 b) {
    vec2 prod = two_prod(a.x, b.x);
    precise float lo = prod.y + (a.x * b.y + a.y * b.x);
    return quick_two_sum(prod.x, lo);
}

vec2 g_of(int row) { return vec2(rows[row].g_hi, rows[row].g_lo); }

// RowMetrics::row_of_g for a double-float G: the row as (whole, frac).
void row_of_g(vec2 value, float mean_rho, out int whole, out float frac) {
    int last = GRID_H - 1;
    whole = 0;
    frac = 0.0;
    if (last == 0 || value.x + value.y <= 0.0) return;
    vec2 top = g_of(last);
    vec2 over = df_add(value, -top);
    if (over.x + over.y >= 0.0) { whole = last; return; }
    int r = clamp(int(value.x / mean_rho), 0, last - 1);
    while (r < last - 1 && rows[r + 1].g_hi < value.x) ++r;
    while (r > 0 && rows[r].g_hi > value.x) --r;
    // The float comparisons above can miss by one row when G ties to float precision.
    for (int i = 0; i < 2; ++i) {
        vec2 rem = df_add(value, -g_of(r));
        float f = (rem.x + rem.y) / rows[r].dg;
        if (f < 0.0 && r > 0) { --r; continue; }
        if (f >= 1.0 && r < last - 1) { ++r; continue; }
        whole = r;
        frac = f;
        return;
    }
    vec2 rem = df_add(value, -g_of(r));
    whole = r;
    frac = (rem.x + rem.y) / rows[r].dg;
}
