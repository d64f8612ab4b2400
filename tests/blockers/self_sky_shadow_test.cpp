// core/blockers/self_sky_shadow: the sky share a mesh's own spheres leave at a surface point,
// against closed forms: one sphere of radius r at distance d straight up hides sin^2 = (r/d)^2;
// the leaf holding the point and leaves behind its tangent plane hide nothing; a leaf next to
// the point fades in over one radius off its surface.
#include "core/blockers/self_sky_shadow.hpp"

#include <gtest/gtest.h>

#include "core/blockers/projected_cover_share.hpp"

namespace ts::blockers {
namespace {

double share_at(const std::vector<Sphere>& spheres, const glm::dvec3& p, const glm::dvec3& n) {
    const auto nodes = flatten_sphere_hierarchy(build_sphere_hierarchy(spheres));
    return self_sky_share(nodes, projected_cover_share(nodes), p, n, 0.05);
}

TEST(SelfSkyShadow, ClosedForms) {
    const glm::dvec3 up(0, 0, 1), origin(0, 0, 0);
    // Radius 5 at 10 m up: sin^2(30 deg) = 0.25 hidden.
    EXPECT_NEAR(share_at({{{0, 0, 10}, 5}}, origin, up), 0.75, 1e-9);
    // Seen from its other side (normal down) it is behind the tangent plane.
    EXPECT_DOUBLE_EQ(share_at({{{0, 0, 10}, 5}}, origin, -up), 1.0);
    // The point inside a leaf: that leaf is its own surface's bound.
    EXPECT_DOUBLE_EQ(share_at({{{0, 0, 1}, 2}}, origin, up), 1.0);
    // A leaf whose surface is half a radius away counts half (smoothstep(0.5) = 0.5): d = 3, r = 2.
    EXPECT_NEAR(share_at({{{0, 0, 3}, 2}}, origin, up), 1.0 - 0.5 * (4.0 / 9.0), 1e-9);
    // Two far spheres side by side: each hides its cap, combined as independent patches.
    const double one = 1.0 - 0.25;
    EXPECT_NEAR(share_at({{{0, 0, 10}, 5}, {{0, 0, -10}, 5}}, origin, up), one, 1e-9);
}

}  // namespace
}  // namespace ts::blockers
