#version 450
// Exact horizons, the sweep (core/visibility/exact_horizons.cpp on the GPU): one invocation per
// line of constant azimuth, all lines of one azimuth in parallel. Each line is walked from the
// far end (where the blockers are), sampled where the CPU samples it (every integer column or
// row, plus the blocker-only points of add_segment_blockers), keeping the upper convex hull of
// the curvature-corrected profile behind it (ProfileHull) with the near field held back in a
// queue (DelayedHull). Every sample inside the receiver window's span writes its far-field
// slope (-infinity if nothing lies far enough behind) and its position across the sweep to
// far[line][along], which stays NaN where the line has no sample (off the grid, in a void);
// vis_exact_finish.comp does the CPU's splat as a gather.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

struct RowInfo { float dx, dy, g_hi, near_steps, g_lo, dg, pad0, pad1; };
struct FarEntry { float slope; float frac; int whole; int pad; };  // slope NaN: no sample; -inf: no far field
// Per line: the first position walked and how many, decided in double on the CPU exactly as
// the CPU sweep decides whether a line is on the grid (a float test would keep or drop lines
// that graze the grid's edge differently), and the line's invariant n * h as a double-float.
struct LineInfo { int first; int count; float nh_hi; float nh_lo; };

layout(std430, set = 0, binding = 0) readonly buffer Heights { float z[]; };
layout(std430, set = 0, binding = 1) readonly buffer Rows { RowInfo rows[]; };
layout(std430, set = 0, binding = 2) buffer Hull { vec2 hull_pts[]; };   // chunk_lines * max_points
layout(std430, set = 0, binding = 3) writeonly buffer Far { FarEntry far[]; };  // [line][along]
layout(std430, set = 0, binding = 4) readonly buffer Lines { LineInfo lines[]; };
// A line's walk continued from the previous pass (see main).
struct WalkState { float s; int prev_whole; float prev_frac; int hull_n; int q_count; int hint; int pad1, pad2; vec4 queue[64]; };
layout(std430, set = 0, binding = 5) buffer States { WalkState states[]; };  // chunk_lines

layout(push_constant) uniform Push {
    int width, height;
    int col0, row0, win_w, win_h;
    int columns;       // 1: lines sampled at every column; 0: at every row
    int n_min;         // invariant index of the first line
    int line_offset;   // first line of this dispatch, counted from n_min
    int span_base;     // this azimuth's first entry in lines
    int chunk_lines;   // lines in this dispatch
    int max_points;    // hull capacity per line
    int step;          // the walk along the sampled axis: +1 or -1
    int k_begin, k_end;  // the samples of this pass
    float cs, sn, curvature, delay, mean_rho;
    // The line's across coordinate at position a is (n h - a m) / c (columns: m = sin, c = cos;
    // rows: (n h - G(a) m) / c with m = cos, c = sin), in double-float: m and 1/c as hi + lo.
    float m_hi, m_lo, inv_hi, inv_lo;
} p;

#define GRID_W p.width
#define GRID_H p.height
#define HEIGHTS_BINDING_1 6
#define HEIGHTS_BINDING_2 7
#define HEIGHTS_BINDING_3 8
#include "gpu/visibility/vis_surface.glsl"

const float kMinCrossing = 1e-3;
const int kQueue = 64;
const int kRebaseEvery = 16;  // line samples between moves of the distance origin

uint hull_base;
int hull_n;
int hint;  // the last query's tangent vertex (hull_query)
// DelayedHull's pending points: (s, u, distance behind the newest line sample). The distance is
// kept small and exact enough for the delay test: s itself reaches ~1e4..1e5 m, where a float
// cannot tell the delay (2 texels) from 2 texels of a slightly narrower row.
vec3 queue[kQueue];
int q_head, q_count;

void hull_insert(vec2 q);

// Every pending point falls `ds` further behind when the line advances by ds.
void queue_advance(float ds) {
    for (int i = 0; i < q_count; ++i) queue[(q_head + i) % kQueue].z += ds;
}

// Moves the origin of distances to `shift` ahead: every stored point becomes
// (s - shift, z - c (s - shift)^2), the same hull up to a shear, so every query answer is
// unchanged. Why: u = z - c s^2 in float loses metres once s reaches 1e6..1e7 m (a 1-degree
// global grid), while relative to a nearby origin the error of each point stays proportional
// to its distance from the query, as its slope tolerates.
void rebase(float shift) {
    for (int i = 0; i < hull_n; ++i) {
        vec2 q = hull_pts[hull_base + uint(i)];
        q.y += p.curvature * shift * (2.0 * q.x - shift);
        q.x -= shift;
        hull_pts[hull_base + uint(i)] = q;
    }
    for (int i = 0; i < q_count; ++i) {
        int j = (q_head + i) % kQueue;
        queue[j].y += p.curvature * shift * (2.0 * queue[j].x - shift);
        queue[j].x -= shift;
    }
}

// ProfileHull::insert.
void hull_insert(vec2 q) {
    while (hull_n >= 2) {
        vec2 a = hull_pts[hull_base + uint(hull_n - 2)];
        vec2 b = hull_pts[hull_base + uint(hull_n - 1)];
        if ((a.y - q.y) * (q.x - b.x) >= (b.y - q.y) * (q.x - a.x)) --hull_n;
        else break;
    }
    if (hull_n < p.max_points) {
        hull_pts[hull_base + uint(hull_n)] = q;
        ++hull_n;
    }
}

// DelayedHull::add, `behind` the next line sample.
void queue_add(float s, float u, float behind) {
    if (q_count == kQueue) {  // never with the default delay; keep the oldest rather than lose it
        hull_insert(queue[q_head].xy);
        q_head = (q_head + 1) % kQueue;
        --q_count;
    }
    queue[(q_head + q_count) % kQueue] = vec3(s, u, behind);
    ++q_count;
}

// Whether the slope from (s, u) to hull vertex k + 1 is at least the slope to vertex k.
bool rises(int k, float s, float u) {
    vec2 a = hull_pts[hull_base + uint(k)];
    vec2 b = hull_pts[hull_base + uint(k + 1)];
    return (b.y - u) * (s - a.x) >= (a.y - u) * (s - b.x);
}

// DelayedHull::query: largest slope from (s, u) to the points at least `delay` behind, found
// as ProfileHull::max_slope_from finds it: walking from the previous tangent vertex to where
// the slopes stop rising. Not by bisection: a crossing just past kMinCrossing puts a sample,
// the midpoint and the crossing a decimetre apart, and after rebase has moved them tens of
// kilometres back their heights carry ~1e-4 m of float rounding, which can dent the chain
// there (seen on a UTM tile: three vertices 0.14 m apart, 35 km back, the middle one below the
// chord of the other two). A bisection that tests that pair can end in the dent, degrees below
// the tangent (the exact method's CPU hull is in double); the walk stays near the tangent.
float hull_query(float s, float u) {
    while (q_count > 0 && queue[q_head].z >= p.delay) {
        hull_insert(queue[q_head].xy);
        q_head = (q_head + 1) % kQueue;
        --q_count;
    }
    if (hull_n == 0) return kNone;
    int i = min(hint, hull_n - 1);
    if (i + 1 < hull_n && rises(i, s, u)) {
        do ++i;
        while (i + 1 < hull_n && rises(i, s, u));
    } else {
        while (i > 0 && !rises(i - 1, s, u)) --i;
    }
    hint = i;
    vec2 t = hull_pts[hull_base + uint(i)];
    return (t.y - u) / (s - t.x);
}

// far_horizon_at: tangent of the far-field elevation (kNone if nothing lies far enough
// behind), then the sample joins the blockers.
float far_horizon_at(float s, float zz) {
    float u = zz - p.curvature * s * s;
    float slope = hull_query(s, u);
    queue_add(s, u, 0.0);
    if (slope == kNone) return kNone;
    return slope - 2.0 * p.curvature * s;
}

// add_segment_blockers: the bilinear surface between two line samples a and b, given as
// offsets from the texel (base_col, base_row) so that texel lines stay exact integers.
void add_segment_blockers(float s, float ds, int base_col, int base_row, vec2 a, vec2 b) {
    float cuts[4];
    int n = 0;
    cuts[n++] = 0.0;
    for (int axis = 0; axis < 2; ++axis) {
        float lo = min(a[axis], b[axis]), hi = max(a[axis], b[axis]), k = ceil(lo);
        if (k > lo && k < hi) {
            float f = (k - a[axis]) / (b[axis] - a[axis]);
            if (f > kMinCrossing && f < 1.0 - kMinCrossing) cuts[n++] = f;
        }
    }
    if (n == 3 && cuts[2] < cuts[1]) { float t = cuts[1]; cuts[1] = cuts[2]; cuts[2] = t; }
    cuts[n++] = 1.0;
    for (int i = 0; i + 1 < n; ++i) {
        float mid = 0.5 * (cuts[i] + cuts[i + 1]);
        for (int j = 0; j < 2; ++j) {
            float f = j == 0 ? mid : cuts[i + 1];
            if (f >= 1.0) break;
            vec2 at = a + f * (b - a);
            float zz = bilinear_valid_at(base_col, base_row, at.x, at.y);
            float sf = s + f * ds;
            if (!isnan(zz)) queue_add(sf, zz - p.curvature * sf * sf, (1.0 - f) * ds);
        }
    }
}

// llvmpipe ends any shader invocation's loops after 65535 iterations in total (gallivm's loop
// limiter, shared by every loop of the shader), which silently cut lines of ~1200 samples
// short. So a line is walked in passes of at most a few hundred samples, one dispatch each,
// the walk's state (queue, hull size, distance) kept in `states` between them.
void main() {
    int local = int(gl_GlobalInvocationID.x);
    if (local >= p.chunk_lines) return;
    int line = p.line_offset + local;  // from n_min
    LineInfo info = lines[p.span_base + line];
    int k_begin = p.k_begin, k_end = min(p.k_end, info.count);
    if (k_begin >= k_end) return;
    vec2 nh = vec2(info.nh_hi, info.nh_lo);
    vec2 m = vec2(p.m_hi, p.m_lo), inv = vec2(p.inv_hi, p.inv_lo);
    hull_base = uint(local) * uint(p.max_points);
    float s = 0.0;
    int prev_whole = 0;
    float prev_frac = 0.0;
    q_head = 0;
    hull_n = 0;
    hint = 0;
    q_count = 0;
    if (k_begin > 0) {
        s = states[local].s;
        prev_whole = states[local].prev_whole;
        prev_frac = states[local].prev_frac;
        hull_n = states[local].hull_n;
        hint = states[local].hint;
        q_count = states[local].q_count;
        for (int i = 0; i < q_count; ++i) queue[i] = states[local].queue[i].xyz;
    }

    int along_len = p.columns == 1 ? p.win_w : p.win_h;
    int along0 = p.columns == 1 ? p.col0 : p.row0;
    uint far_base = uint(line) * uint(along_len);  // far starts all NaN (filled before pass 0)
    float abs_cs = abs(p.cs), abs_sn = abs(p.sn);
    for (int k = k_begin; k < k_end; ++k) {
        int a = info.first + k * p.step;
        int whole;
        float frac, zz;
        if (p.columns == 1) {
            // sweep_columns: the line's G at column a, then its row.
            vec2 gv = df_mul(df_add(nh, -df_mul(vec2(float(a), 0.0), m)), inv);
            row_of_g(gv, p.mean_rho, whole, frac);
            if (k > 0) {
                float mid = 0.5 * (float(prev_whole - whole) + prev_frac + frac);
                float mid_floor = floor(mid);
                float ds = spacing_at(whole + int(mid_floor), mid - mid_floor).x / abs_cs;
                queue_advance(ds);
                add_segment_blockers(s, ds, a - p.step, prev_whole, vec2(0.0, prev_frac),
                                     vec2(float(p.step), float(whole - prev_whole) + frac));
                s += ds;
            }
            zz = sample_column(a, whole, frac);
        } else {
            // sweep_rows: the line's column at row a, clamped onto the grid.
            vec2 col = df_mul(df_add(nh, -df_mul(g_of(a), m)), inv);
            float w = floor(col.x);
            frac = (col.x - w) + col.y;
            whole = int(w);
            if (frac < 0.0) { --whole; frac += 1.0; }
            if (frac >= 1.0) { ++whole; frac -= 1.0; }
            if (whole < 0) { whole = 0; frac = 0.0; }
            if (whole >= p.width - 1) { whole = p.width - 1; frac = 0.0; }
            if (k > 0) {
                float ds = 0.5 * (rows[a].dy + rows[a - p.step].dy) / abs_sn;
                queue_advance(ds);
                add_segment_blockers(s, ds, prev_whole, a - p.step, vec2(prev_frac, 0.0),
                                     vec2(float(whole - prev_whole) + frac, float(p.step)));
                s += ds;
            }
            zz = sample_row(a, whole, frac);
        }
        prev_whole = whole;
        prev_frac = frac;
        if (k % kRebaseEvery == 0) {
            rebase(s);
            s = 0.0;
        }
        if (isnan(zz)) continue;  // inside a void: neither blocks nor receives
        float slope = far_horizon_at(s, zz);
        int i = a - along0;
        if (i >= 0 && i < along_len) far[far_base + uint(i)] = FarEntry(slope, frac, whole, 0);
    }
    states[local].s = s;
    states[local].prev_whole = prev_whole;
    states[local].prev_frac = prev_frac;
    states[local].hull_n = hull_n;
    states[local].hint = hint;
    states[local].q_count = q_count;
    for (int i = 0; i < q_count; ++i) states[local].queue[i] = vec4(queue[(q_head + i) % kQueue], 0.0);
}
