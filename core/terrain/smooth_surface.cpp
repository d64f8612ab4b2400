#include "core/terrain/smooth_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/terrain/valid_bilinear.hpp"

namespace ts::terrain {
namespace {

// The patch's 4x4 heights (rows row-1..row+2, columns col-1..col+2), or false when one of its
// 2x2 corners is a void. Outer heights that are voids or off the grid are extrapolated
// linearly from the two inner ones on their line.
bool fill_patch(const HeightGrid& g, int col, int row, float p[4][4]) {
    if (col >= 1 && row >= 1 && col + 2 < g.width && row + 2 < g.height) {
        // Inside the grid (the common case): 16 loads; any void sends it the slow way.
        float sum = 0;
        for (int j = 0; j < 4; ++j) {
            const float* line = &g.z[g.index(col - 1, row - 1 + j)];
            for (int i = 0; i < 4; ++i) sum += p[j][i] = line[i];
        }
        if (!std::isnan(sum)) return true;
    }
    auto get = [&](int c, int r) {
        return c >= 0 && r >= 0 && c < g.width && r < g.height ? g.at(c, r) : std::numeric_limits<float>::quiet_NaN();
    };
    for (int j = 1; j <= 2; ++j)
        for (int i = 1; i <= 2; ++i) {
            p[j][i] = get(col + i - 1, row + j - 1);
            if (std::isnan(p[j][i])) return false;
        }
    for (int j = 1; j <= 2; ++j) {
        p[j][0] = get(col - 1, row + j - 1);
        if (std::isnan(p[j][0])) p[j][0] = 2 * p[j][1] - p[j][2];
        p[j][3] = get(col + 2, row + j - 1);
        if (std::isnan(p[j][3])) p[j][3] = 2 * p[j][2] - p[j][1];
    }
    for (int i = 0; i < 4; ++i) {
        p[0][i] = get(col + i - 1, row - 1);
        if (std::isnan(p[0][i])) p[0][i] = 2 * p[1][i] - p[2][i];
        p[3][i] = get(col + i - 1, row + 2);
        if (std::isnan(p[3][i])) p[3][i] = 2 * p[2][i] - p[1][i];
    }
    return true;
}

void catmull_rom(float t, float w[4], float d[4]) {
    const float t2 = t * t, t3 = t2 * t;
    w[0] = 0.5f * (-t3 + 2 * t2 - t);
    w[1] = 0.5f * (3 * t3 - 5 * t2 + 2);
    w[2] = 0.5f * (-3 * t3 + 4 * t2 + t);
    w[3] = 0.5f * (t3 - t2);
    d[0] = 0.5f * (-3 * t2 + 4 * t - 1);
    d[1] = 0.5f * (9 * t2 - 10 * t);
    d[2] = 0.5f * (-9 * t2 + 8 * t + 1);
    d[3] = 0.5f * (3 * t2 - 2 * t);
}

// The derivatives of the uniform cubic B-spline's weights at t in [0, 1] between knots 1 and 2:
// at t = 0 the central difference about knot 1, at t = 1 about knot 2.
void b_spline_derivative(float t, float d[4]) {
    const float u = 1 - t, t2 = t * t;
    d[0] = -0.5f * u * u;
    d[1] = 0.5f * (3 * t2 - 4 * t);
    d[2] = 0.5f * (-3 * t2 + 2 * t + 1);
    d[3] = 0.5f * t2;
}

}  // namespace

SurfaceSample smooth_slope(const HeightGrid& g, double x, double y) {
    float fx = 0, fy = 0;
    const int c = valid_bilinear_corner(std::clamp(x, 0.0, double(std::max(g.width - 1, 0))), g.width, fx);
    const int r = valid_bilinear_corner(std::clamp(y, 0.0, double(std::max(g.height - 1, 0))), g.height, fy);
    float p[4][4];
    if (!(g.width >= 2 && g.height >= 2 && fill_patch(g, c, r, p))) return smooth_surface(g, x, y);
    // Across each axis Catmull-Rom's weights, which on a texel centre's own line take that line
    // alone; along it the B-spline's derivative, which at a texel centre is the central difference.
    float cr_x[4], dcr_x[4], cr_y[4], dcr_y[4], db_x[4], db_y[4];
    catmull_rom(fx, cr_x, dcr_x);
    catmull_rom(fy, cr_y, dcr_y);
    b_spline_derivative(fx, db_x);
    b_spline_derivative(fy, db_y);
    float z = 0, zc = 0, zr = 0;
    for (int j = 0; j < 4; ++j) {
        float along = 0, across = 0;
        for (int i = 0; i < 4; ++i) along += db_x[i] * p[j][i], across += cr_x[i] * p[j][i];
        z += cr_y[j] * across, zc += cr_y[j] * along, zr += db_y[j] * across;
    }
    SurfaceSample s;
    s.z = z, s.dz_dcol = zc, s.dz_drow = zr;
    return s;
}

SurfaceSample smooth_surface(const HeightGrid& g, double x, double y) {
    float fx = 0, fy = 0;
    const int c = valid_bilinear_corner(std::clamp(x, 0.0, double(std::max(g.width - 1, 0))), g.width, fx);
    const int r = valid_bilinear_corner(std::clamp(y, 0.0, double(std::max(g.height - 1, 0))), g.height, fy);
    SurfaceSample s;
    float p[4][4];
    if (g.width >= 2 && g.height >= 2 && fill_patch(g, c, r, p)) {
        float wx[4], dx[4], wy[4], dy[4];
        catmull_rom(fx, wx, dx);
        catmull_rom(fy, wy, dy);
        float z = 0, zc = 0, zr = 0;
        for (int j = 0; j < 4; ++j) {
            float row = 0, row_d = 0;
            for (int i = 0; i < 4; ++i) row += wx[i] * p[j][i], row_d += dx[i] * p[j][i];
            z += wy[j] * row, zc += wy[j] * row_d, zr += dy[j] * row;
        }
        s.z = z, s.dz_dcol = zc, s.dz_drow = zr;
        return s;
    }
    const int c1 = std::min(c + 1, g.width - 1), r1 = std::min(r + 1, g.height - 1);
    const float z00 = g.at(c, r), z10 = g.at(c1, r), z01 = g.at(c, r1), z11 = g.at(c1, r1);
    s.z = blend_valid_corners(z00, z10, z01, z11, fx, fy);
    // The slope along each axis from the corner pairs that have both heights.
    auto pair_slope = [](float a, float b, float wa, float wb) {
        float sum = 0, weight = 0;
        if (!std::isnan(a)) sum += wa * a, weight += wa;
        if (!std::isnan(b)) sum += wb * b, weight += wb;
        return weight > 0 ? sum / weight : 0.0f;
    };
    s.dz_dcol = pair_slope(z10 - z00, z11 - z01, 1 - fy, fy);
    s.dz_drow = pair_slope(z01 - z00, z11 - z10, 1 - fx, fx);
    return s;
}

float smooth_patch_bound(const HeightGrid& g, int col, int row) {
    float p[4][4];
    if (fill_patch(g, col, row, p)) {
        float lo = p[0][0], hi = p[0][0];
        for (const auto& line : p)
            for (float z : line) lo = std::min(lo, z), hi = std::max(hi, z);
        return hi + 0.28125f * (hi - lo);
    }
    float m = -std::numeric_limits<float>::infinity();
    for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di) {
            const int c = std::min(col + di, g.width - 1), r = std::min(row + dj, g.height - 1);
            const float z = g.at(c, r);
            if (!std::isnan(z)) m = std::max(m, z);
        }
    return m;
}

}  // namespace ts::terrain
