// A sphere's sun shadow on flat ground found at any point (PixelSunBlockers) against its
// geometry, on texels coarser than the shadow: the ellipse of semi-axes r (across the sun) and
// r / sin e (along it), h / tan e down-sun of the point under the sphere.
#include "core/render/pixel_sun_blockers.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/blockers/sphere_hierarchy.hpp"
#include "core/geo/azimuth.hpp"
#include "core/util/angles.hpp"
#include "core/visibility/blocker_sun_shadow.hpp"

namespace ts::render {
namespace {

TEST(PixelSunBlockers, FindsASphereShadowSmallerThanATexel) {
    // 10 m texels; a sphere of radius 4 m 30 m up: a shadow 8 m across, less than a texel.
    const int w = 41, h = 41;
    const double ground = 100, r = 4, up = 30, az = 135, el = 35;
    std::vector<float> z(std::size_t(w * h), float(ground));
    const terrain::HeightGrid grid = terrain::HeightGrid::uniform(w, h, z, 10.0, 10.0);
    blockers::SphereBlockers b;
    blockers::PlacedSpheres p;
    p.anchor = {20.0, 20.0};
    p.spheres = {{{0.0, 0.0, ground + up}, r}};
    p.hierarchy = blockers::build_sphere_hierarchy(p.spheres);
    b.meshes.push_back(p);
    PixelSunBlockers pixels(grid, b, 0.0);
    const glm::dvec3 sun = geo::enu_direction(geo::azimuth_cw_from_north_to_phi(az), radians(el));
    pixels.set_sun(sun);

    const double shift = up / std::tan(radians(el));
    const glm::dvec2 u(std::sin(radians(az)), std::cos(radians(az)));  // towards the sun
    const glm::dvec2 centre = -u * shift;                             // metres from the anchor
    long long both = 0, either = 0;
    for (double y = 15; y <= 25; y += 0.05)
        for (double x = 15; x <= 25; x += 0.05) {
            const glm::dvec2 q((x - 20) * 10, (20 - y) * 10);
            const glm::dvec2 d = q - centre;
            const double along = glm::dot(d, u), across = u.x * d.y - u.y * d.x;
            const bool analytic = std::pow(along * std::sin(radians(el)) / r, 2) + std::pow(across / r, 2) <= 1.0;
            const bool got = pixels.visible(x, y, ground) < 0.5;
            both += analytic && got, either += analytic || got;
        }
    ASSERT_GT(either, 0);
    EXPECT_GE(double(both) / double(either), 0.98);  // measured 1.000
    RecordProperty("iou", std::to_string(double(both) / double(either)));

    // At texel centres: what the texels' pass finds.
    std::vector<float> texel(z.size(), 1.0f);
    visibility::BlockerSunShadow(grid, b, 0.0, 1).apply(az, el, texel);
    for (int row = 0; row < h; ++row)
        for (int col = 0; col < w; ++col)
            EXPECT_NEAR(pixels.visible(col, row, ground), texel[grid.index(col, row)], 1e-5) << col << "," << row;
}

}  // namespace
}  // namespace ts::render
