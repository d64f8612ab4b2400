// The sphere blockers against the real triangles, ray-traced through a BVH
// (core/visibility/blocker_reference.hpp): the BVH itself, and the sun shadow of the shared
// Cessna on a sloping field at 64 spheres (the footprint's IoU with the triangles' shadow).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/blockers/sphere_decomposition.hpp"
#include "core/blockers/triangle_bvh.hpp"
#include "core/geo/azimuth.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/util/angles.hpp"
#include "core/visibility/blocker_reference.hpp"
#include "core/visibility/blocker_sun_shadow.hpp"

namespace ts::visibility {
namespace {

TEST(TriangleBvh, FindsTheTrianglesARayMeetsAndNoOthers) {
    // A grid of 20 x 20 unit squares (800 triangles) in the plane z = 5, every other square
    // left out: rays straight up hit exactly where a square is.
    std::vector<glm::dvec3> p;
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j) {
            if ((i + j) % 2) continue;
            const glm::dvec3 a(i, j, 5), b(i + 1, j, 5), c(i + 1, j + 1, 5), d(i, j + 1, 5);
            p.insert(p.end(), {a, b, c, a, c, d});
        }
    const blockers::TriangleBvh bvh(p);
    EXPECT_EQ(bvh.triangles(), 400u);
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j) {
            const glm::dvec3 o(i + 0.3, j + 0.6, 0);
            EXPECT_EQ(bvh.occluded(o, glm::dvec3(0, 0, 1)), (i + j) % 2 == 0) << i << ' ' << j;
            EXPECT_FALSE(bvh.occluded(o, glm::dvec3(0, 0, -1)));
            EXPECT_FALSE(bvh.occluded(o, glm::dvec3(0, 0, 1), 4.9));  // stops short of the plane
        }
    // Oblique, through the far side of the plane.
    EXPECT_TRUE(bvh.occluded(glm::dvec3(-5, 0.5, 0), glm::dvec3(1.1, 0, 1)));
}

TEST(BlockerReference, ACessnaAt64SpheresCastsTheSunShadowOfItsTriangles) {
    // The shared Cessna 15 m over a field sloping up to the east (1 in 10), 0.25 m texels;
    // sun from the south-west, 40 deg up. Shadow: texels with less than half the disc.
    const mesh::TriangleMesh cessna = mesh::import_mesh(std::filesystem::path(TS_SHARED_DATA) / "meshes" / "c172p.ac");
    blockers::DecompositionOptions d;
    d.count = 64;
    d.threads = 2;
    const blockers::SphereDecomposition dec = blockers::decompose_into_spheres(cessna, d);

    const int n = 240;
    const double cell = 0.25;
    std::vector<float> z(std::size_t(n) * n);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) z[std::size_t(r) * n + c] = float(0.1 * cell * c);
    const terrain::HeightGrid grid = terrain::HeightGrid::uniform(n, n, z, cell, cell);
    mesh::Placement place;
    place.height_m = 15.0;
    place.above_ground = true;
    place.heading_deg = 30.0;
    place.pitch_deg = 5.0;
    const glm::dvec2 anchor(n / 2.0, n / 2.0);
    const double ground = 0.1 * cell * anchor.x;

    blockers::SphereBlockers spheres;
    spheres.meshes.push_back(blockers::place_spheres(dec.spheres, place, anchor, ground, "c172p"));
    const PlacedTriangles tris = place_triangles(cessna, place, anchor, ground);

    const double az = 225.0, el = 40.0;
    const glm::dvec3 sun = geo::enu_direction(geo::azimuth_cw_from_north_to_phi(az), radians(el));
    ReferenceOptions ro;
    ro.threads = 2;
    // Cast by the spheres, then (the default) by the triangles where the spheres shadow.
    for (const auto caster : {blockers::SphereBlockerOptions::SunCaster::spheres,
                              blockers::SphereBlockerOptions::SunCaster::triangles}) {
        const bool by_triangles = caster == blockers::SphereBlockerOptions::SunCaster::triangles;
        spheres.options.sun_caster = caster;
        spheres.meshes[0].model_triangles = by_triangles ? blockers::model_triangle_bvh(cessna) : nullptr;
        const BlockerSunShadow shadow(grid, spheres, 0.0, 2);
        std::vector<float> ours(z.size(), 1.0f);
        shadow.apply(az, el, ours);
        const TexelRect rect = shadow.footprint(0, az, el);
        ASSERT_FALSE(rect.empty());
        const std::vector<float> ref = reference_sun(grid, tris, rect, sun, spheres.options.sun_radius_rad, 0.0, ro);
        long long both = 0, either = 0, ref_count = 0, outside = 0;
        double se = 0;
        for (int r = 0; r < n; ++r)
            for (int c = 0; c < n; ++c) {
                const bool in_rect = rect.contains(c, r);
                const float want =
                    in_rect ? ref[std::size_t(r - rect.row0) * std::size_t(rect.col1 - rect.col0) + std::size_t(c - rect.col0)]
                            : 1.0f;
                const float got = ours[std::size_t(r) * n + c];
                const bool s = got < 0.5f, t = want < 0.5f;
                both += s && t, either += s || t, ref_count += t, outside += s && !in_rect;
                se += double(got - want) * double(got - want);
            }
        const double iou = double(both) / double(either);
        const double recall = double(both) / double(ref_count);
        const double rmse = std::sqrt(se / double(z.size()));
        std::printf("sun shadow cast by the %s: %lld texels (triangles), IoU %.3f, share of the triangles' shadow "
                    "covered %.3f, RMSE of the visible disc %.4f\n",
                    by_triangles ? "triangles" : "spheres", ref_count, iou, recall, rmse);
        EXPECT_EQ(outside, 0);
        EXPECT_GT(ref_count, 300);  // the shadow spans many texels: the IoU means something
        // Bounding spheres shadow all the triangles do (less a penumbra texel here and there)...
        EXPECT_GE(recall, 0.97);
        if (by_triangles) {
            // ...so the rays through the triangles, cast where the spheres shadow, miss none of it.
            EXPECT_GE(iou, 0.97);  // the goal: 0.9 at 64 spheres
            EXPECT_LT(rmse, 0.01);
        } else {
            // ...and more: thin wings and struts are bounded by spheres far thicker than they are.
            EXPECT_GE(iou, 0.68);  // measured 0.706
        }
    }
}

}  // namespace
}  // namespace ts::visibility
