// Which spheres of a mesh darken a receiver's sky: the solid-angle threshold is the mesh's
// (its bounding sphere's), so a fine decomposition keeps the shadow its union casts; spheres
// wholly below the receiver's tangent plane are dropped.
#include "core/blockers/receiver_blockers.hpp"

#include <vector>

#include <gtest/gtest.h>

#include "core/blockers/sphere_hierarchy.hpp"

namespace ts::blockers {
namespace {

// A 4 m ball made of 8x8x8 small spheres, 20 m above the origin.
PlacedSpheres fine_ball() {
    PlacedSpheres m;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j)
            for (int k = 0; k < 8; ++k)
                m.spheres.push_back({glm::dvec3(-1.75 + 0.5 * i, -1.75 + 0.5 * j, 18.25 + 0.5 * k), 0.45});
    m.hierarchy = build_sphere_hierarchy(m.spheres);
    return m;
}

TEST(ReceiverBlockers, AFineDecompositionKeepsTheShadowOfItsUnion) {
    const PlacedSpheres m = fine_ball();
    const double min_sine = min_cap_sine(0.01);
    // From 30 m below and to the side, each small sphere subtends ~7e-4 sr, the ball ~0.05 sr.
    const glm::dvec3 receiver(10, 0, -5), up(0, 0, 1);
    const Sphere root = m.hierarchy.nodes[0].bound;
    ASSERT_GT(root.radius / glm::length(root.center - receiver), min_sine);
    ASSERT_LT(0.45 / glm::length(m.spheres[0].center - receiver), min_sine);
    std::vector<Sphere> seen;
    collect_sky_blockers(m, receiver, up, min_sine, {}, seen);
    EXPECT_EQ(seen.size(), m.spheres.size());
    // Far away the whole mesh falls below the threshold: nothing.
    seen.clear();
    collect_sky_blockers(m, glm::dvec3(500, 0, 0), up, min_sine, {}, seen);
    EXPECT_TRUE(seen.empty());
}

TEST(ReceiverBlockers, SpheresBelowTheTangentPlaneAreDropped) {
    const PlacedSpheres m = fine_ball();
    std::vector<Sphere> seen;
    // A receiver on a vertical wall facing away from the ball, level with its middle: the half
    // of the ball behind the wall's plane (x < 0.1 - r) is culled.
    collect_sky_blockers(m, glm::dvec3(0.1, 0, 20), glm::dvec3(1, 0, 0), min_cap_sine(0.01), {}, seen);
    EXPECT_GT(seen.size(), 0u);
    EXPECT_LT(seen.size(), m.spheres.size());
    for (const Sphere& s : seen) EXPECT_GT(s.center.x, -s.radius);
    seen.clear();
    RatioAttenuation keep_all;
    keep_all.cull_lower_hemisphere = false;
    collect_sky_blockers(m, glm::dvec3(0.1, 0, 20), glm::dvec3(1, 0, 0), min_cap_sine(0.01), keep_all, seen);
    EXPECT_EQ(seen.size(), m.spheres.size());
}

}  // namespace
}  // namespace ts::blockers
