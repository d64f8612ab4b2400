// The sphere hierarchy: every node's sphere holds its children's, so it holds every leaf below.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "core/blockers/sphere_hierarchy.hpp"

namespace {
using ts::blockers::Sphere;

bool holds(const Sphere& outer, const Sphere& inner) {
    return glm::length(inner.center - outer.center) + inner.radius <= outer.radius * (1 + 1e-12) + 1e-12;
}

TEST(SphereHierarchy, ParentsBoundChildrenAndEveryLeafOnce) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-5, 5), r(0.05, 1.5);
    for (int n : {1, 2, 3, 8, 64, 511}) {
        std::vector<Sphere> spheres;
        for (int i = 0; i < n; ++i) spheres.push_back({{u(rng), u(rng), 0.2 * u(rng)}, r(rng)});
        const auto h = ts::blockers::build_sphere_hierarchy(spheres);
        ASSERT_EQ(int(h.nodes.size()), 2 * n - 1);
        std::vector<int> seen(std::size_t(n), 0);
        for (const auto& node : h.nodes) {
            if (node.is_leaf()) {
                ++seen[std::size_t(node.sphere)];
                EXPECT_EQ(node.bound.radius, spheres[std::size_t(node.sphere)].radius);
                continue;
            }
            EXPECT_TRUE(holds(node.bound, h.nodes[std::size_t(node.left)].bound));
            EXPECT_TRUE(holds(node.bound, h.nodes[std::size_t(node.right)].bound));
        }
        for (int s : seen) EXPECT_EQ(s, 1);
        for (const auto& s : spheres) EXPECT_TRUE(holds(h.nodes[0].bound, s));
    }
}

// The flattened tree walked without a stack (as the flythrough's shaders do) finds exactly the
// leaves visit_leaves finds, for a test that a sphere inside a refused one fails too (a point's
// distance to the sphere below a limit).
TEST(SphereHierarchy, TheFlatWalkFindsTheLeavesOfTheTreeWalk) {
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> u(-5, 5), r(0.05, 1.5);
    for (int n : {1, 2, 7, 64, 400}) {
        std::vector<Sphere> spheres;
        for (int i = 0; i < n; ++i) spheres.push_back({{u(rng), u(rng), 0.2 * u(rng)}, r(rng)});
        const auto h = ts::blockers::build_sphere_hierarchy(spheres);
        const auto flat = ts::blockers::flatten_sphere_hierarchy(h);
        ASSERT_EQ(flat.size(), h.nodes.size());
        for (int k = 0; k < 20; ++k) {
            const glm::dvec3 p(u(rng), u(rng), u(rng));
            const double limit = 0.5 * (u(rng) + 5.0);
            auto keep = [&](const Sphere& s) { return glm::length(s.center - p) - s.radius < limit; };
            std::vector<int> tree, walk;
            ts::blockers::visit_leaves(h, keep, [&](int i) { tree.push_back(i); });
            int visited = 0;
            for (int i = 0; i < int(flat.size());) {
                ++visited;
                const bool accepted = keep(flat[std::size_t(i)].bound);
                if (accepted && flat[std::size_t(i)].sphere >= 0) walk.push_back(flat[std::size_t(i)].sphere);
                i = accepted ? i + 1 : flat[std::size_t(i)].skip;
            }
            EXPECT_EQ(walk, tree) << n << " spheres, query " << k;
            EXPECT_LE(visited, int(flat.size()));
        }
    }
}

TEST(SphereHierarchy, EnclosingSphereOfNestedAndDisjoint) {
    const Sphere big{{0, 0, 0}, 2}, small{{0.5, 0, 0}, 1};
    EXPECT_EQ(ts::blockers::enclosing_sphere(big, small).radius, 2.0);
    const auto e = ts::blockers::enclosing_sphere({{0, 0, 0}, 1}, {{4, 0, 0}, 1});
    EXPECT_NEAR(e.radius, 3.0, 1e-9);
    EXPECT_NEAR(e.center.x, 2.0, 1e-9);
}

}  // namespace
