#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/terrain/smooth_surface.hpp"
#include "core/terrain/terrain_normals.hpp"

namespace ts::terrain {
namespace {

// A rough 24x20 grid (two scales of waves and noise), 30 m x 20 m texels.
struct RoughGrid {
    int w = 24, h = 20;
    std::vector<float> z;
    HeightGrid grid;
    RoughGrid() : z(std::size_t(24 * 20)) {
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> noise(-15.0f, 15.0f);
        for (int r = 0; r < h; ++r)
            for (int c = 0; c < w; ++c)
                z[std::size_t(r * w + c)] = 500 + 80 * std::sin(0.5f * c) * std::cos(0.4f * r) + noise(rng);
        grid = HeightGrid::uniform(w, h, z, 30.0, 20.0);
    }
};

TEST(SmoothSurface, PassesThroughEveryHeight) {
    const RoughGrid g;
    for (int r = 0; r < g.h; ++r)
        for (int c = 0; c < g.w; ++c) EXPECT_NEAR(smooth_surface(g.grid, c, r).z, g.grid.at(c, r), 1e-3f) << c << "," << r;
}

TEST(SmoothSurface, SlopesAtTexelCentresAreTheNormalsCentralDifferences) {
    // Per-pixel normals agree with the per-texel ones (terrain_normals) at the texel centres,
    // the edges (one-sided differences) included.
    const RoughGrid g;
    const render::NormalField n = render::terrain_normals(g.grid, 1);
    for (int r = 0; r < g.h; ++r)
        for (int c = 0; c < g.w; ++c) {
            const SurfaceSample s = smooth_surface(g.grid, c, r);
            const double gx = s.dz_dcol / 30.0, gy = -s.dz_drow / 20.0;
            const double len = std::sqrt(gx * gx + gy * gy + 1);
            const std::size_t i = g.grid.index(c, r);
            EXPECT_NEAR(-gx / len, n.x[i], 1e-5) << c << "," << r;
            EXPECT_NEAR(-gy / len, n.y[i], 1e-5) << c << "," << r;
        }
}

TEST(SmoothSurface, HasNoCreaseAlongTexelLines) {
    // C1: height and slope agree from both sides of a patch edge (a bilinear surface's slope
    // across the edge jumps).
    const RoughGrid g;
    const double e = 1e-4;
    for (int c = 1; c < g.w - 1; ++c)
        for (double y : {3.3, 7.8, 12.5}) {
            const SurfaceSample left = smooth_surface(g.grid, c - e, y), right = smooth_surface(g.grid, c + e, y);
            EXPECT_NEAR(left.z, right.z, 0.05f);
            EXPECT_NEAR(left.dz_dcol, right.dz_dcol, 0.05f) << c << "," << y;
            EXPECT_NEAR(left.dz_drow, right.dz_drow, 0.05f);
        }
}

TEST(SmoothSlope, AtTexelCentresItIsTheSurfacesSlopeAndAPlaneIsExact) {
    const RoughGrid g;
    for (int r = 0; r < g.h; ++r)
        for (int c = 0; c < g.w; ++c) {
            const SurfaceSample a = smooth_slope(g.grid, c, r), b = smooth_surface(g.grid, c, r);
            EXPECT_NEAR(a.dz_dcol, b.dz_dcol, 1e-3f) << c << "," << r;
            EXPECT_NEAR(a.dz_drow, b.dz_drow, 1e-3f) << c << "," << r;
        }
    std::vector<float> plane(std::size_t(g.w * g.h));
    for (int r = 0; r < g.h; ++r)
        for (int c = 0; c < g.w; ++c) plane[std::size_t(r * g.w + c)] = 100 + 3.0f * c - 2.0f * r;
    const HeightGrid p = HeightGrid::uniform(g.w, g.h, plane, 30.0, 20.0);
    for (double x : {0.0, 2.25, 7.5, 22.9})
        for (double y : {0.0, 4.6, 18.2}) {
            EXPECT_NEAR(smooth_slope(p, x, y).dz_dcol, 3.0f, 1e-3f);
            EXPECT_NEAR(smooth_slope(p, x, y).dz_drow, -2.0f, 1e-3f);
        }
}

TEST(SmoothSlope, ItsSlopeBendsWithoutACreaseWhereCatmullRomsDoes) {
    // The shading follows the slope: a kink in the slope along a texel line is a line in the
    // picture. Catmull-Rom's slope is continuous there, its rate of change is not; the
    // B-spline's derivative along the axis changes smoothly.
    const RoughGrid g;
    const double e = 1e-3;
    double kink_slope = 0, kink_surface = 0;
    for (int c = 2; c < g.w - 2; ++c)
        for (double y : {3.3, 7.8, 12.5}) {
            auto kink = [&](auto f) {
                const double l = (f(c).dz_dcol - f(c - e).dz_dcol) / e, r = (f(c + e).dz_dcol - f(c).dz_dcol) / e;
                return std::abs(r - l);
            };
            kink_slope = std::max(kink_slope, kink([&](double x) { return smooth_slope(g.grid, x, y); }));
            kink_surface = std::max(kink_surface, kink([&](double x) { return smooth_surface(g.grid, x, y); }));
        }
    EXPECT_LT(kink_slope, 0.05 * kink_surface) << kink_slope << " " << kink_surface;
}

TEST(SmoothSurface, PatchBoundHoldsOverThePatch) {
    // The bound the marches skip cells by: never below the surface, sampled densely, on a grid
    // with cliffs (where Catmull-Rom overshoots most).
    RoughGrid g;
    for (int r = 0; r < g.h; ++r)
        for (int c = 0; c < g.w; ++c)
            if ((c / 3 + r / 4) % 2) g.z[std::size_t(r * g.w + c)] += 400;
    for (int r = 0; r + 1 < g.h; ++r)
        for (int c = 0; c + 1 < g.w; ++c) {
            const float bound = smooth_patch_bound(g.grid, c, r);
            float top = -1e30f;
            for (int j = 0; j <= 16; ++j)
                for (int i = 0; i <= 16; ++i) top = std::max(top, smooth_surface(g.grid, c + i / 16.0, r + j / 16.0).z);
            EXPECT_GE(bound, top) << c << "," << r;
        }
}

TEST(SmoothSurface, VoidsFallBackToTheValidBilinearBlend) {
    RoughGrid g;
    g.z[std::size_t(5 * g.w + 6)] = NAN;
    // A patch with the void as a corner: the valid corners' blend, finite slopes.
    const SurfaceSample s = smooth_surface(g.grid, 5.5, 5.5);
    EXPECT_TRUE(std::isfinite(s.z));
    EXPECT_TRUE(std::isfinite(s.dz_dcol) && std::isfinite(s.dz_drow));
    EXPECT_NEAR(smooth_surface(g.grid, 5.0, 5.0).z, g.grid.at(5, 5), 1e-3f);
    // A patch that only has the void among its outer heights stays smooth and finite.
    const SurfaceSample t = smooth_surface(g.grid, 7.5, 4.5);
    EXPECT_TRUE(std::isfinite(t.z));
    // All four corners void: no surface.
    for (int r = 9; r <= 10; ++r)
        for (int c = 9; c <= 10; ++c) g.z[std::size_t(r * g.w + c)] = NAN;
    EXPECT_TRUE(std::isnan(smooth_surface(g.grid, 9.5, 9.5).z));
    EXPECT_EQ(smooth_patch_bound(g.grid, 9, 9), -std::numeric_limits<float>::infinity());
}

}  // namespace
}  // namespace ts::terrain
