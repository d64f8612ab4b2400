#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/terrain/terrain_normals.hpp"
#include "core/util/angles.hpp"

namespace ts::render {
namespace {

TEST(TerrainNormals, PlaneTiltedEastWithMetricSpacing) {
    // z = 0.5 * east metres: the normal is (-0.5, 0, 1)/|.| whatever the spacing in texels.
    const int w = 6, h = 5;
    const double dx = 30.0, dy = 20.0;
    std::vector<float> z(w * h);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) z[r * w + c] = float(0.5 * c * dx);
    const auto g = terrain::HeightGrid::uniform(w, h, z, dx, dy);
    const NormalField n = terrain_normals(g);
    const double len = std::sqrt(1.25);
    for (std::size_t i = 0; i < z.size(); ++i) {  // edges too (one-sided differences are exact on a plane)
        EXPECT_NEAR(n.x[i], -0.5 / len, 1e-6);
        EXPECT_NEAR(n.y[i], 0.0, 1e-6);
        EXPECT_NEAR(n.z[i], 1.0 / len, 1e-6);
    }
    EXPECT_NEAR(slope_deg(n.z[0]), degrees(std::atan(0.5)), 1e-4);
}

TEST(TerrainNormals, RowsRunSouthSoHeightRisingNorthFacesSouth) {
    // Height grows towards row 0 (north): the slope faces south, n.y < 0.
    const int w = 3, h = 4;
    std::vector<float> z(w * h);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) z[r * w + c] = float((h - r) * 10.0);
    const auto g = terrain::HeightGrid::uniform(w, h, z, 10.0, 10.0);
    const NormalField n = terrain_normals(g);
    EXPECT_NEAR(n.y[4], -std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(n.z[4], std::sqrt(0.5), 1e-6);
}

TEST(TerrainNormals, PerRowSpacingChangesTheSlope) {
    // The same height step per texel, but row 1 is twice as wide east-west: half the slope.
    const int w = 3, h = 2;
    std::vector<float> z = {0, 10, 20, 0, 10, 20};
    terrain::HeightGrid g = terrain::HeightGrid::uniform(w, h, z, 10.0, 10.0);
    g.dx_m[1] = 20.0;
    const NormalField n = terrain_normals(g);
    EXPECT_NEAR(n.x[1] / n.z[1], -1.0, 1e-6);
    EXPECT_NEAR(n.x[4] / n.z[4], -0.5, 1e-6);
}

TEST(TerrainNormals, ARowAtAPoleHasNoEastWestSlope) {
    // A global grid's row centred on a pole is one point (dx_m 0): its normals stay finite (its
    // insolation was NaN), with the north-south slope alone.
    std::vector<float> z = {5, 7, 9, 0, 0, 0, 0, 0, 0};
    terrain::HeightGrid g = terrain::HeightGrid::uniform(3, 3, z, 10.0, 10.0);
    g.dx_m[0] = 0.0;
    const NormalField n = terrain_normals(g);
    for (int c = 0; c < 3; ++c) {
        EXPECT_TRUE(std::isfinite(n.x[std::size_t(c)]) && std::isfinite(n.z[std::size_t(c)])) << c;
        EXPECT_EQ(n.x[std::size_t(c)], 0.0f) << c;
    }
}

TEST(TerrainNormals, HolesAreSkipped) {
    std::vector<float> z = {0, 0, 0, 0, NAN, 0, 0, 0, 0};
    const auto g = terrain::HeightGrid::uniform(3, 3, z, 10.0, 10.0);
    const NormalField n = terrain_normals(g);
    for (std::size_t i = 0; i < z.size(); ++i) EXPECT_FLOAT_EQ(n.z[i], 1.0f) << i;
}

}  // namespace
}  // namespace ts::render
