// Which spheres of a mesh darken a receiver's sky: the solid-angle threshold is applied down
// the sphere hierarchy (a sphere above it counts; a node above it whose children are each below
// it counts whole), so finer decompositions of one shape keep the same shadow; spheres wholly
// below the receiver's tangent plane are dropped.
#include "core/blockers/receiver_blockers.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/blockers/sphere_hierarchy.hpp"
#include "core/util/angles.hpp"

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

// A slab 40 x 8 x 1 m (a wing), its centre 20 m up, cut into nx x ny x nz cells, one sphere
// circumscribing each: the same shape at sphere counts from 8 to 512.
PlacedSpheres slab(int nx, int ny, int nz) {
    const glm::dvec3 size(40, 8, 1), low(-20, -4, 19.5);
    const glm::dvec3 cell = size / glm::dvec3(nx, ny, nz);
    PlacedSpheres m;
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j)
            for (int k = 0; k < nz; ++k)
                m.spheres.push_back({low + cell * glm::dvec3(i + 0.5, j + 0.5, k + 0.5), 0.5 * glm::length(cell)});
    m.hierarchy = build_sphere_hierarchy(m.spheres);
    return m;
}

// Share of 12k directions, spread evenly over the cap that `bound` (relative to the receiver at
// the origin, not containing it) subtends, that meet one of the spheres: their union's solid
// angle, in units of the cap's.
double union_share(const std::vector<Sphere>& spheres, const Sphere& bound) {
    const double dist = glm::length(bound.center);
    const glm::dvec3 w = bound.center / dist;
    const glm::dvec3 u = glm::normalize(glm::cross(w, std::abs(w.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0)));
    const glm::dvec3 v = glm::cross(w, u);
    const double cos_cap = std::sqrt(1.0 - bound.radius * bound.radius / (dist * dist));
    const int n = 12000;
    int hit = 0;
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - (1.0 - cos_cap) * (i + 0.5) / n, rho = std::sqrt(1.0 - z * z);
        const double phi = i * 2.399963229728653;
        const glm::dvec3 d = z * w + rho * std::cos(phi) * u + rho * std::sin(phi) * v;
        for (const Sphere& s : spheres) {
            const double along = glm::dot(s.center, d);
            if (along > 0.0 && glm::dot(s.center, s.center) - along * along <= s.radius * s.radius) {
                ++hit;
                break;
            }
        }
    }
    return double(hit) / n;
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
    // Each sphere alone is below the threshold; the ball's pieces above it keep them.
    EXPECT_GT(seen.size(), m.spheres.size() / 2);
    // Far away the whole mesh falls below the threshold: nothing.
    seen.clear();
    collect_sky_blockers(m, glm::dvec3(500, 0, 0), up, min_sine, {}, seen);
    EXPECT_TRUE(seen.empty());
}

TEST(ReceiverBlockers, ASphereAboveTheThresholdAlwaysCountsAndOneBelowBesideItIsDropped) {
    // A big sphere and a small one side by side: from 100 m the big one subtends ~0.08 sr, the
    // small one ~3e-4 sr (below 0.01 sr).
    PlacedSpheres m;
    m.spheres = {{glm::dvec3(0, 0, 100), 16.0}, {glm::dvec3(30, 0, 100), 1.0}};
    m.hierarchy = build_sphere_hierarchy(m.spheres);
    std::vector<Sphere> seen;
    collect_sky_blockers(m, glm::dvec3(0.0), glm::dvec3(0, 0, 1), min_cap_sine(0.01), {}, seen);
    ASSERT_EQ(seen.size(), 1u);
    EXPECT_EQ(seen[0].radius, 16.0);
}

TEST(ReceiverBlockers, TheKeptShadowConvergesWithTheSphereCount) {
    // The same slab at 8, 64 and 512 spheres, seen from receivers on the ground at growing
    // distances, where its spheres are above, around and below the threshold. What the
    // threshold drops is a few parts of less than it each, whatever the count: the solid angle
    // the kept spheres' union leaves out of all spheres' union stays below a fifth of the
    // threshold (0.002 sr, 0.06% of a cosine-weighted sky) at every count, so 8, 64 and 512
    // spheres agree to within it. Keeping only the spheres that pass the threshold alone loses more than half
    // of the union at 512 (the contrast, so the test can fail).
    const double min_sr = 0.01, min_sine = min_cap_sine(min_sr);
    const PlacedSpheres sets[] = {slab(4, 2, 1), slab(8, 4, 2), slab(16, 8, 4)};
    const glm::dvec3 up(0, 0, 1);
    for (double x : {30.0, 80.0, 150.0, 250.0}) {
        const glm::dvec3 receiver(x, 10, 0);
        const Sphere bound{glm::dvec3(0, 0, 20) - receiver, 20.5};  // holds every set
        const double d = glm::length(bound.center);
        const double cap_sr = 2.0 * kPi * (1.0 - std::sqrt(1.0 - bound.radius * bound.radius / (d * d)));
        double whole[3], lost[3];
        for (int k = 0; k < 3; ++k) {
            const PlacedSpheres& m = sets[k];
            std::vector<Sphere> all, seen;
            for (const Sphere& s : m.spheres) all.push_back({s.center - receiver, s.radius});
            collect_sky_blockers(m, receiver, up, min_sine, {}, seen);
            whole[k] = cap_sr * union_share(all, bound);
            lost[k] = whole[k] - cap_sr * union_share(seen, bound);
            EXPECT_LE(lost[k], 0.2 * min_sr) << "x " << x << " set " << k;
            if (k == 2) {
                std::vector<Sphere> alone;
                for (const Sphere& s : all)
                    if (s.radius / glm::length(s.center) > min_sine) alone.push_back(s);
                const double alone_lost = whole[k] - cap_sr * union_share(alone, bound);
                std::printf("x %5.0f m: union %.4f sr; kept leaves out %.4f %.4f %.4f sr (8, 64, 512 spheres); "
                            "per sphere alone %.4f sr\n", x, whole[k], lost[0], lost[1], lost[2], alone_lost);
                EXPECT_GT(alone_lost, 0.5 * whole[k]) << "x " << x;
            }
        }
    }
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
