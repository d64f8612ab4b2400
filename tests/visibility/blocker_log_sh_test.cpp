// The sphere blockers' log-SH added to a grid's texels (blocker_log_sh.hpp), by both ways of
// picking the spheres a texel sums (SphereBlockerOptions::sky_culling): without culling every
// texel where a mesh's bounding sphere passes the threshold gets exactly the double-precision
// sum over all its spheres (accumulate_blockers), the others nothing; through the hierarchy
// fewer pairs for a sky within a few hundredths of it.
#include "core/visibility/blocker_log_sh.hpp"

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <gtest/gtest.h>

#include "core/blockers/sphere_hierarchy.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/visibility/blocker_footprint.hpp"
#include "core/visibility/blocker_reference.hpp"
#include "tests/visibility/synthetic_terrain.hpp"

namespace ts::visibility {
namespace {

using Culling = blockers::SphereBlockerOptions::SkyCulling;

// A cluster of n spheres (an aircraft's worth) 40 m over the anchor.
blockers::PlacedSpheres cluster(glm::dvec2 anchor, int n, unsigned seed, double ground) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-12.0, 12.0), ur(0.8, 3.0);
    blockers::PlacedSpheres p;
    p.anchor = anchor;
    for (int i = 0; i < n; ++i) p.spheres.push_back({{u(rng), 0.4 * u(rng), ground + 40.0 + 0.2 * u(rng)}, ur(rng)});
    p.hierarchy = blockers::build_sphere_hierarchy(p.spheres);
    return p;
}

struct Added {
    std::vector<float> log_sh;
    BlockerStageStats stats;
};

Added run(const terrain::HeightGrid& g, const blockers::SphereBlockers& b) {
    Added out;
    out.log_sh.assign(16 * g.z.size(), 0.0f);
    out.stats = add_blocker_log_sh(g, {0, 0, g.width, g.height}, b, 0.0, 2, out.log_sh.data());
    return out;
}

// Sky visibility of the blockers alone (exp of their log-SH against the cosine lobe) at texel t.
double sky(const Added& r, std::size_t t, std::size_t texels, const sh::ShVec& lobe) {
    return sky_visibility_of_log_sh(r.log_sh.data() + t, texels, sh::ExpMethod::scaling_squaring, lobe);
}

const testing::Terrain& hills() {
    static const testing::Terrain t = testing::make_terrain(
        90, 80, 10.0, 10.0, [](double x, double y) { return 100.0 + 6.0 * std::sin(0.02 * x) * std::cos(0.03 * y); });
    return t;
}

TEST(BlockerLogSh, WithoutCullingACountingTexelSumsEverySphereAndTheOthersNothing) {
    const terrain::HeightGrid& g = hills().grid;
    blockers::SphereBlockers b;
    b.meshes.push_back(cluster({45.0, 40.0}, 40, 3, 100.0));
    b.options.sky_culling = Culling::none;
    const Added got = run(g, b);
    const render::NormalField normals = render::terrain_normals(g, 2);
    const blockers::Sphere& root = b.meshes[0].hierarchy.nodes[0].bound;
    const double min_sine = blockers::min_cap_sine(b.options.min_solid_angle_sr);
    long long counting = 0;
    for (int r = 0; r < g.height; r += 3)
        for (int c = 0; c < g.width; c += 3) {
            const std::size_t t = g.index(c, r);
            const glm::dvec3 q = receiver_in_anchor_frame(g, c, r, b.meshes[0], 0.0);
            const double d = glm::length(root.center - q);
            const bool counts = d <= root.radius || root.radius / d > min_sine;
            sh::ShVec want{};
            if (counts) {
                want = blockers::accumulate_blockers(b.meshes[0].spheres, q, {normals.x[t], normals.y[t], normals.z[t]},
                                                     b.options.log_eps, b.options.attenuation);
                ++counting;
            }
            double scale = 1e-3;
            for (double v : want) scale = std::max(scale, std::abs(v));
            for (int i = 0; i < 16; ++i)
                ASSERT_NEAR(got.log_sh[std::size_t(i) * g.z.size() + t], want[std::size_t(i)], 1e-4 * scale)
                    << "texel " << c << "," << r << " coefficient " << i;
        }
    EXPECT_GT(counting, 100);  // the footprint holds much of the grid, not all of it
    EXPECT_LT(counting, 90 * 80 / 9);
}

TEST(BlockerLogSh, TheHierarchySumsFewerPairsForASkyCloseToEverySpheres) {
    const terrain::HeightGrid& g = hills().grid;
    blockers::SphereBlockers b;
    b.meshes.push_back(cluster({45.0, 40.0}, 120, 5, 100.0));
    b.options.sky_culling = Culling::none;
    const Added all = run(g, b);
    b.options.sky_culling = Culling::hierarchy;
    const Added tree = run(g, b);
    EXPECT_LT(tree.stats.sphere_texel_pairs, all.stats.sphere_texel_pairs);
    EXPECT_GT(tree.stats.sphere_texel_pairs, 0);
    const sh::ShVec lobe = zenith_cosine_lobe();  // a quadrature: once
    double worst = 0.0;
    for (std::size_t t = 0; t < g.z.size(); ++t)
        worst = std::max(worst, std::abs(sky(all, t, g.z.size(), lobe) - sky(tree, t, g.z.size(), lobe)));
    std::printf("hierarchy against every sphere: %lld against %lld pairs, sky visibility max %.4f apart\n",
                tree.stats.sphere_texel_pairs, all.stats.sphere_texel_pairs, worst);
    EXPECT_LT(worst, 0.05);  // the dropped caps: a few hundredths of the cosine-weighted sky at most
}

TEST(BlockerLogSh, TwoMeshesAreAttenuatedTogetherWithoutCulling) {
    // Two clusters side by side (different anchors): a texel seeing both sums all their spheres
    // in one set, so the ratio attenuation sees them together, as the hierarchy path does.
    const terrain::HeightGrid& g = hills().grid;
    blockers::SphereBlockers b;
    b.meshes.push_back(cluster({40.0, 40.0}, 30, 7, 100.0));
    b.meshes.push_back(cluster({52.0, 38.0}, 30, 8, 100.0));
    b.options.sky_culling = Culling::none;
    const Added got = run(g, b);
    const render::NormalField normals = render::terrain_normals(g, 2);
    for (const glm::ivec2 at : {glm::ivec2(46, 40), glm::ivec2(30, 50), glm::ivec2(60, 30)}) {
        const std::size_t t = g.index(at.x, at.y);
        std::vector<blockers::Sphere> relative;
        for (const blockers::PlacedSpheres& m : b.meshes) {
            const glm::dvec3 q = receiver_in_anchor_frame(g, at.x, at.y, m, 0.0);
            for (const blockers::Sphere& s : m.spheres) relative.push_back({s.center - q, s.radius});
        }
        const sh::ShVec want = blockers::accumulate_blockers(relative, glm::dvec3(0.0),
                                                             {normals.x[t], normals.y[t], normals.z[t]},
                                                             b.options.log_eps, b.options.attenuation);
        double scale = 0.0;
        for (double v : want) scale = std::max(scale, std::abs(v));
        ASSERT_GT(scale, 0.01);
        for (int i = 0; i < 16; ++i)
            EXPECT_NEAR(got.log_sh[std::size_t(i) * g.z.size() + t], want[std::size_t(i)], 1e-4 * scale) << i;
    }
}

}  // namespace
}  // namespace ts::visibility
