// core/render/open_sky_fraction: the cosine-weighted share of the sky a texel sees, through the
// frames' own transfer: ~1 on open flat ground, and at the bottom of a V valley with walls at
// beta cos(beta) (the 2D view factor of the opening) read up to ~0.1 bright by the order-4
// truncation of exp(V_log + log cosine) (the mesh-vertex route of point_terrain_light_test.cpp
// measures the same +0.004..+0.094). The frame's sky term comes through the same transfer, so
// their ratio, which the flythrough uses, is the albedo times the sky's radiance either way;
// and the share of the sky term a blocker in the open sky removes (ts_open_sky_share).
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "core/blockers/sphere_occlusion_shared.hpp"
#include "core/render/open_sky_fraction.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "tests/render/frame_stack.hpp"
#include "tests/render/grey_materials.hpp"

namespace ts::render {
namespace {

// The open-sky fraction at the centre texel of a V valley along the rows, walls at beta.
double valley_floor(double beta_deg) {
    const int w = 161, h = 61;
    const double spacing = 10.0, t = std::tan(beta_deg * 3.14159265358979 / 180.0);
    std::vector<float> z(std::size_t(w) * h);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r) * w + c] = float(t * std::abs(c - w / 2) * spacing);
    const terrain::HeightGrid grid = terrain::HeightGrid::uniform(w, h, z, spacing, spacing);
    RendererOptions o;
    o.directions = 32;
    o.curvature = false;
    testing::FrameStack stack(grid, testing::grey_materials(grid, 0.3f), terrain_normals(grid), {}, o);
    const std::vector<float> v = open_sky_fraction(*stack.frame);
    EXPECT_EQ(v.size(), std::size_t(w) * h);
    for (const float x : v) {
        EXPECT_GE(x, 0.0f);
        EXPECT_LE(x, 1.0f);
    }
    return v[std::size_t(h / 2) * w + w / 2];
}

TEST(OpenSkyFraction, OpenGroundSeesAllOfItAValleyFloorCosBeta) {
    const double open = valley_floor(0.0);
    EXPECT_GT(open, 0.9);
    EXPECT_LE(open, 1.0);
    double previous = open;
    for (const double beta : {20.0, 35.0, 50.0}) {
        const double floor = valley_floor(beta);
        EXPECT_LT(floor, previous) << beta;
        previous = floor;
        const double want = std::cos(beta * 3.14159265358979 / 180.0);
        std::printf("V valley beta %.0f deg: open-sky fraction %.4f, / open ground %.4f, cos(beta) %.4f\n", beta,
                    floor, floor / open, want);
        EXPECT_GE(floor / open, want - 0.01) << beta;
        EXPECT_LE(floor / open, want + 0.1) << beta;
    }
}

TEST(OpenSkyFraction, ABlockerInTheOpenSkyTakesItsShareOfWhatTheTerrainLeaves) {
    using blockers::shared::ts_open_sky_share;
    EXPECT_DOUBLE_EQ(ts_open_sky_share(0.1, 1.0), 0.1);   // open ground: its cover
    EXPECT_DOUBLE_EQ(ts_open_sky_share(0.1, 0.5), 0.2);   // half the sky left: twice the share
    EXPECT_DOUBLE_EQ(ts_open_sky_share(0.3, 0.2), 1.0);   // covers all the terrain leaves
    EXPECT_DOUBLE_EQ(ts_open_sky_share(0.01, 0.0), 0.2);  // the floor: no division by 0
    EXPECT_DOUBLE_EQ(ts_open_sky_share(0.0, 0.3), 0.0);
}

}  // namespace
}  // namespace ts::render
