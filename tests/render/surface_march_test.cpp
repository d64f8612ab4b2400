#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/render/surface_march.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/util/angles.hpp"
#include "core/visibility/sun_visibility.hpp"

namespace ts::render {
namespace {

constexpr double kSunRadius = 0.004654;

glm::dvec3 sun_from(double azimuth_deg, double elevation_deg) {
    const double a = radians(azimuth_deg), e = radians(elevation_deg);
    return {std::sin(a) * std::cos(e), std::cos(a) * std::cos(e), std::sin(e)};
}

TEST(SurfaceMarch, FindsAPlateausShadowEdgeWithinAFractionOfATexel) {
    // A plateau 50 m above the plain (columns 0..20, 10 m texels), the sun in the west 30
    // degrees up: the edge (column 20) shades the plain 50 / tan 30 = 86.6 m = 8.66 texels
    // beyond it. The smooth surface overshoots the edge by 3.7 m two thirds of a texel inside
    // (at column 19.67, so its shadow reaches 19.67 + 53.7 / (10 tan 30) = 28.97): the edge of
    // the shadow falls between columns 28.66 and 29.0 plus the penumbra; the disc's penumbra is a
    // tenth of a texel wide, and the pixel rays find it so (a blend of the texels' visible
    // fractions spreads it over a whole texel).
    const int w = 64, h = 16;
    std::vector<float> z(std::size_t(w * h), 100.0f);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c <= 20; ++c) z[std::size_t(r * w + c)] = 150.0f;
    const terrain::HeightGrid g = terrain::HeightGrid::uniform(w, h, z, 10.0, 10.0);
    const SurfaceMarch march(g, 1);
    const glm::dvec3 sun = sun_from(270, 30);
    double half = -1, lit = -1, dark = -1;
    for (double x = 26.0; x <= 31.0; x += 0.01) {
        const double v = march.sun_visible_fraction(x, 8.0, sun, kSunRadius, 0.0);
        if (v > 0.05 && dark < 0) dark = x;
        if (v >= 0.5 && half < 0) half = x;
        if (v > 0.95 && lit < 0) lit = x;
    }
    EXPECT_GT(half, 28.6);
    EXPECT_LT(half, 29.1);
    EXPECT_LT(lit - dark, 0.2);
    EXPECT_DOUBLE_EQ(march.sun_visible_fraction(25.0, 8.0, sun, kSunRadius, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(march.sun_visible_fraction(35.0, 8.0, sun, kSunRadius, 0.0), 1.0);
    // The sun behind the plateau's back (east): nothing on the plain is shaded.
    EXPECT_DOUBLE_EQ(march.sun_visible_fraction(25.0, 8.0, sun_from(90, 30), kSunRadius, 0.0), 1.0);
}

TEST(SurfaceMarch, SunVisibilityAgreesWithTheExactPathAtTexelCentres) {
    // Smooth hills (where a bilinear and a bicubic surface are close), the sun low in the
    // south-west: the pixel rays from texel centres against visibility::sun_visibility, as the
    // sun's diffuse term v max(0, n.s) (along the terminators, where the slope towards the sun
    // is about the sun's elevation, the two surfaces disagree on v, and n.s is about 0).
    const int w = 96, h = 96;
    std::vector<float> z(std::size_t(w * h));
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c)
            z[std::size_t(r * w + c)] = float(300 * std::exp(-((c - 40.0) * (c - 40.0) + (r - 50.0) * (r - 50.0)) / 200.0) +
                                              120 * std::sin(0.15 * c) * std::sin(0.11 * r));
    const terrain::HeightGrid g = terrain::HeightGrid::uniform(w, h, z, 30.0, 30.0);
    const SurfaceMarch march(g, 1);
    const NormalField normals = terrain_normals(g, 1);
    for (const double elevation : {8.0, 20.0}) {
        visibility::SunVisibilityOptions so;
        so.curvature = false;
        so.threads = 1;
        const std::vector<float> exact = visibility::sun_visibility(g, 225, elevation, so);
        const glm::dvec3 sun = sun_from(225, elevation);
        double sum = 0, lit = 0;
        int n = 0, disagree = 0;
        for (int r = 0; r < h; ++r)
            for (int c = 0; c < w; ++c) {
                const std::size_t t = g.index(c, r);
                const double cos_s = std::max(0.0, normals.x[t] * sun.x + normals.y[t] * sun.y + normals.z[t] * sun.z);
                const double v = march.sun_visible_fraction(c, r, sun, kSunRadius, 0.0);
                sum += std::abs(v - exact[t]) * cos_s;
                lit += exact[t] * cos_s;
                disagree += cos_s > 0.1 && (v < 0.5) != (exact[t] < 0.5);
                ++n;
            }
        EXPECT_LT(sum / lit, 0.01) << elevation;
        EXPECT_LT(double(disagree) / n, 0.002) << elevation;
        RecordProperty("relative_diff_" + std::to_string(int(elevation)), std::to_string(sum / lit));
    }
}

}  // namespace
}  // namespace ts::render
