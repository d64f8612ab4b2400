// Hillshade on planes with known slope and aspect: the exact value of 1 + 254 cos(incidence).
#include "core/render/hillshade.hpp"
#include "core/util/angles.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/util/error.hpp"

namespace ts::render {
namespace {


// A plane z = gx * east + gy * north (metres), on a grid with spacings dx, dy (row 0 = north).
std::vector<float> plane(int w, int h, double dx, double dy, double gx, double gy) {
    std::vector<float> z(std::size_t(w) * std::size_t(h));
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r * w + c)] = float(1000.0 + gx * c * dx + gy * (h - 1 - r) * dy);
    return z;
}

// The expected grey value from slope and aspect, computed independently of the Horn code:
// cos(i) = cos(zenith) cos(slope) + sin(zenith) sin(slope) cos(azimuth - aspect), with aspect
// the downhill direction clockwise from north.
int expected_value(double gx, double gy, double azimuth_deg, double altitude_deg) {
    const double slope = std::atan(std::hypot(gx, gy));
    const double aspect = std::atan2(-gx, -gy);  // downhill direction, clockwise from north
    const double zenith = radians(90.0 - altitude_deg);
    const double cos_i =
        std::cos(zenith) * std::cos(slope) + std::sin(zenith) * std::sin(slope) * std::cos(radians(azimuth_deg) - aspect);
    return cos_i <= 0 ? 1 : int(std::lround(1.0 + 254.0 * cos_i));
}

struct PlaneCase { double gx, gy, azimuth, altitude, dx, dy; };
class HillshadePlanes : public ::testing::TestWithParam<PlaneCase> {};

TEST_P(HillshadePlanes, InteriorEqualsTheAnalyticShadeAndBorderIsNodata) {
    const PlaneCase k = GetParam();
    const int w = 9, h = 7;
    const std::vector<float> z = plane(w, h, k.dx, k.dy, k.gx, k.gy);
    const terrain::HeightGrid grid = terrain::HeightGrid::uniform(w, h, z, k.dx, k.dy);
    const std::vector<std::uint8_t> out =
        hillshade(grid, {.azimuth_deg = k.azimuth, .altitude_deg = k.altitude, .compute_edges = false});
    const int want = expected_value(k.gx, k.gy, k.azimuth, k.altitude);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            const bool border = r == 0 || c == 0 || r == h - 1 || c == w - 1;
            // Exact: the Horn gradient of a plane is exact; float heights ~1000 m lose < 1e-4 m.
            ASSERT_EQ(int(out[std::size_t(r * w + c)]), border ? 0 : want) << c << "," << r;
        }
}

// With edges computed (the default) a plane's border is exact too: the outside cells are
// extrapolated linearly, which a plane continues exactly. Only the four corners differ: there
// gdaldem clamps the columns, halving the east-west difference.
TEST_P(HillshadePlanes, EdgesOfAPlaneAreExactButTheCorners) {
    const PlaneCase k = GetParam();
    const int w = 9, h = 7;
    const std::vector<float> z = plane(w, h, k.dx, k.dy, k.gx, k.gy);
    const terrain::HeightGrid grid = terrain::HeightGrid::uniform(w, h, z, k.dx, k.dy);
    const std::vector<std::uint8_t> out = hillshade(grid, {.azimuth_deg = k.azimuth, .altitude_deg = k.altitude});
    const int want = expected_value(k.gx, k.gy, k.azimuth, k.altitude);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            const bool corner = (r == 0 || r == h - 1) && (c == 0 || c == w - 1);
            const int v = out[std::size_t(r * w + c)];
            if (corner) {
                EXPECT_GE(v, 1) << c << "," << r;
                if (k.gx == 0) {  // no east-west slope to halve
                    EXPECT_EQ(v, want) << c << "," << r;
                }
            } else {
                ASSERT_EQ(v, want) << c << "," << r;
            }
        }
}

INSTANTIATE_TEST_SUITE_P(
    KnownSlopes, HillshadePlanes,
    ::testing::Values(PlaneCase{0, 0, 315, 45, 30, 30},            // flat: 1 + 254 sin(45) = 181
                      PlaneCase{-1, 0, 90, 45, 30, 30},            // 45 deg slope facing east, lit from east: 255
                      PlaneCase{1, 0, 90, 45, 30, 30},             // facing west, lit from east at 45: grazing -> 1
                      PlaneCase{0, 0.5, 0, 30, 25, 40},            // rising northward, lit from north
                      PlaneCase{0, -0.5, 0, 30, 25, 40},           // facing north
                      PlaneCase{0.3, -0.2, 315, 45, 90, 92.6},     // non-square cells (geographic-like)
                      PlaneCase{-0.7, 0.4, 200, 10, 20, 20},       // low sun
                      PlaneCase{2.0, 1.0, 45, 80, 5, 5}));         // steep

TEST(Hillshade, FlatGroundIsOnePlus254SinAltitude) {
    std::vector<float> z(25, 100.0f);
    const auto out = hillshade(terrain::HeightGrid::uniform(5, 5, z, 30, 30), {.altitude_deg = 30});
    EXPECT_EQ(out[12], 1 + 127);  // 1 + 254 * 0.5
}

TEST(Hillshade, ZFactorScalesTheGradient) {
    // A 0.25 slope facing east with z-factor 4 is a 45 degree slope: lit from the east at 45 -> 255.
    const std::vector<float> z = plane(5, 5, 10, 10, -0.25, 0);
    const auto out = hillshade(terrain::HeightGrid::uniform(5, 5, z, 10, 10), {.azimuth_deg = 90, .z_factor = 4});
    EXPECT_EQ(out[12], 255);
}

TEST(Hillshade, PerRowSpacingIsUsed) {
    // Same heights, east-west spacing halved on the middle row only: the slope doubles there.
    const int w = 5, h = 5;
    const std::vector<float> z = plane(w, h, 10, 10, -0.5, 0);
    terrain::HeightGrid g = terrain::HeightGrid::uniform(w, h, z, 10, 10);
    g.dx_m[2] = 5;
    const auto out = hillshade(g, {.azimuth_deg = 90, .altitude_deg = 45});
    EXPECT_EQ(int(out[std::size_t(1 * w + 2)]), expected_value(-0.5, 0, 90, 45));
    EXPECT_EQ(int(out[std::size_t(2 * w + 2)]), expected_value(-1.0, 0, 90, 45));
}

TEST(Hillshade, VoidsAndTheirNeighboursAreNodataWithoutEdges) {
    const int w = 7, h = 7;
    std::vector<float> z(std::size_t(w * h), 50.0f);
    z[std::size_t(3 * w + 3)] = std::nanf("");
    std::vector<std::uint8_t> mask(std::size_t(w * h), 0);
    mask[std::size_t(1 * w + 1)] = 1;  // a filled void: height present, still nodata
    terrain::HeightGrid g = terrain::HeightGrid::uniform(w, h, z, 1, 1);
    g.void_mask = mask;
    const auto out = hillshade(g, {.compute_edges = false});
    for (int r = 1; r < h - 1; ++r)
        for (int c = 1; c < w - 1; ++c) {
            const bool near_hole = std::abs(r - 3) <= 1 && std::abs(c - 3) <= 1;
            const bool filled_void = r == 1 && c == 1;
            EXPECT_EQ(out[std::size_t(r * w + c)], near_hole || filled_void ? 0 : 181) << c << "," << r;
        }
}

// With edges (the default) a hole's neighbours are shaded with the hole taking their height,
// as gdaldem -compute_edges; the hole and a filled void stay nodata; the border is shaded.
TEST(Hillshade, EdgesShadeTheRimsOfHolesAndTheBorder) {
    const int w = 7, h = 7;
    std::vector<float> z(std::size_t(w * h), 50.0f);
    z[std::size_t(3 * w + 3)] = std::nanf("");
    z[std::size_t(0 * w + 4)] = std::nanf("");  // a hole on the border
    std::vector<std::uint8_t> mask(std::size_t(w * h), 0);
    mask[std::size_t(1 * w + 1)] = 1;
    terrain::HeightGrid g = terrain::HeightGrid::uniform(w, h, z, 1, 1);
    g.void_mask = mask;
    const auto out = hillshade(g, {});
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            const bool nodata = (r == 3 && c == 3) || (r == 0 && c == 4) || (r == 1 && c == 1);
            EXPECT_EQ(out[std::size_t(r * w + c)], nodata ? 0 : 181) << c << "," << r;
        }
}

TEST(Hillshade, TinyGrids) {
    std::vector<float> z(5, 1.0f);
    // 2x2: nodata without edges (no 3x3 window), flat shade with them.
    for (auto v : hillshade(terrain::HeightGrid::uniform(2, 2, z, 1, 1), {.compute_edges = false})) EXPECT_EQ(v, 0);
    for (auto v : hillshade(terrain::HeightGrid::uniform(2, 2, z, 1, 1), {})) EXPECT_EQ(v, 181);
    // A single row or column has no gradient across it: nodata either way.
    for (auto v : hillshade(terrain::HeightGrid::uniform(5, 1, z, 1, 1), {})) EXPECT_EQ(v, 0);
    for (auto v : hillshade(terrain::HeightGrid::uniform(1, 5, z, 1, 1), {})) EXPECT_EQ(v, 0);
}

TEST(Hillshade, ThreadCountDoesNotChangeTheResult) {
    const int w = 300, h = 301;
    std::vector<float> z(std::size_t(w * h));
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r * w + c)] = float(100 * std::sin(c * 0.05) * std::cos(r * 0.03));
    const auto g = terrain::HeightGrid::uniform(w, h, z, 30, 30);
    EXPECT_EQ(hillshade(g, {.threads = 1}), hillshade(g, {.threads = 3}));
}

TEST(Hillshade, RejectsBadOptions) {
    std::vector<float> z(9, 1.0f);
    const auto g = terrain::HeightGrid::uniform(3, 3, z, 1, 1);
    EXPECT_THROW(hillshade(g, {.altitude_deg = 91}), InputError);
    EXPECT_THROW(hillshade(g, {.altitude_deg = -1}), InputError);
    EXPECT_THROW(hillshade(g, {.azimuth_deg = std::nan("")}), InputError);
    EXPECT_THROW(hillshade(g, {.z_factor = 0}), InputError);
    EXPECT_THROW(hillshade(g, {.z_factor = INFINITY}), InputError);
}

}  // namespace
}  // namespace ts::render
