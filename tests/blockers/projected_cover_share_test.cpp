// core/blockers/projected_cover_share: the share of a node's bound disc its leaves' discs cover,
// seen along z, against closed forms.
#include "core/blockers/projected_cover_share.hpp"

#include <vector>

#include <gtest/gtest.h>

namespace ts::blockers {
namespace {

std::vector<FlatSphereNode> flat(const std::vector<Sphere>& spheres) {
    return flatten_sphere_hierarchy(build_sphere_hierarchy(spheres));
}

TEST(ProjectedCoverShare, ClosedForms) {
    // Two spheres of radius 1 side by side along x: their bound has radius 2 and they cover half
    // its disc's area (2 pi / 4 pi).
    const auto two = flat({{{-1, 0, 0}, 1.0}, {{1, 0, 0}, 1.0}});
    ASSERT_EQ(two.size(), 3u);
    const std::vector<float> s = projected_cover_share(two, 200);
    EXPECT_NEAR(s[0], 0.5, 0.01);
    EXPECT_EQ(s[1], 1.0f);
    EXPECT_EQ(s[2], 1.0f);
    // The same two stacked along z: seen from below they are one disc of radius 1 in the bound's
    // of radius 2 (a quarter), where scattering them independently would say 1 - (3/4)^2.
    const auto stacked = flat({{{0, 0, -1}, 1.0}, {{0, 0, 1}, 1.0}});
    EXPECT_NEAR(projected_cover_share(stacked, 200)[0], 0.25, 0.01);
    // One sphere inside another: the bound is the larger, fully covered.
    const auto nested = flat({{{0, 0, 0}, 2.0}, {{0.5, 0, 0}, 1.0}});
    EXPECT_NEAR(projected_cover_share(nested, 200)[0], 1.0, 1e-6);
}

}  // namespace
}  // namespace ts::blockers
