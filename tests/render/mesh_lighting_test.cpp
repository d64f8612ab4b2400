// Meshes lit per vertex over synthetic terrains: the sky a point at the bottom of a V valley
// gets against the analytic cos(beta), a receiver inside a sphere ignoring it, 500 overlapping
// spheres kept finite, a mesh below the terrain or off the DEM, and the rasteriser's depth test
// against the terrain.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/blockers/self_shadow.hpp"
#include "core/render/mesh_lighting.hpp"
#include "core/render/mesh_view.hpp"
#include "core/sh/exp_method.hpp"
#include "core/sh/sh_basis.hpp"
#include "core/sh/sphere_quadrature.hpp"
#include "core/util/angles.hpp"
#include "core/visibility/horizon_sh.hpp"
#include "tests/render/uniform_sky.hpp"
#include "tests/support/sun_direction.hpp"

namespace ts::render {
namespace {

// Uniform radiance 1 over the upper hemisphere and a sun disc of irradiance e.
using testing::UniformSky;

struct Terrain {
    std::vector<float> z;
    terrain::HeightGrid grid;
    Terrain(int w, int h, double spacing, auto f) : z(std::size_t(w) * h) {
        for (int r = 0; r < h; ++r)
            for (int c = 0; c < w; ++c) z[std::size_t(r) * w + c] = float(f((c - w / 2) * spacing, (h / 2 - r) * spacing));
        grid = terrain::HeightGrid::uniform(w, h, z, spacing, spacing);
    }
};

// One small horizontal triangle (normal up, white) centred on the anchor at height z.
PlacedMesh tile_at(glm::dvec2 anchor, double z, double size = 1.0) {
    PlacedMesh m;
    m.anchor = anchor;
    m.positions = {{-size, -size, z}, {size, -size, z}, {0.0, size, z}};
    m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    m.albedo = {glm::vec3(1.0f)};
    return m;
}

using ts::test::sun_from;

TEST(MeshLighting, AtTheBottomOfAVValleyTheSkyIsCosBeta) {
    const UniformSky sky(sun_from(180, 45), 0.0f);
    const light::SkySh sh = light::project_sky_sh(sky);
    MeshLightingOptions o;
    o.curvature = false;
    o.self_shadow = false;
    for (const double beta_deg : {0.0, 20.0, 35.0, 50.0}) {
        const double t = std::tan(radians(beta_deg));
        const Terrain v(301, 301, 10.0, [&](double x, double) { return t * std::abs(x); });
        const MeshLighting lit(v.grid, tile_at({150, 150}, 0.05), nullptr, {}, o);
        std::vector<glm::vec3> rad;
        lit.radiance(sh, sky.sun(), false, rad);
        // Uniform radiance 1: the upward side's sky term is its cosine-weighted visible fraction.
        const double got = rad[0].x, want = std::cos(radians(beta_deg));
        std::printf("V valley beta %4.1f deg: sky %.4f, analytic cos(beta) %.4f, error %+.4f\n", beta_deg, got, want,
                    got - want);
        // Order-4 log-SH with the terrain's floor log 0.1 lets ~0.1 through below the horizons
        // and smooths the walls' edges, the texels' own error (docs/blockers.md has the figures:
        // -0.004 .. -0.084 at 0 .. 50 deg).
        EXPECT_NEAR(got, want, 0.1) << beta_deg;
        // The downward side sees no sky at all from the valley floor.
        EXPECT_LT(rad[3].x, 0.12);
    }
}

TEST(MeshLighting, BehindARidgeTheMeshLosesTheSunAndInFrontKeepsIt) {
    const Terrain ridge(201, 201, 20.0, [](double x, double) { return std::max(0.0, 300.0 - std::abs(x)); });
    MeshLightingOptions o;
    o.curvature = false;
    const MeshLighting east(ridge.grid, tile_at({140, 100}, 50.0), nullptr, {}, o);
    std::vector<float> vis;
    east.sun_visibility(sun_from(270, 10), vis);  // the crest is 17 deg up from there
    for (float v : vis) EXPECT_EQ(v, 0.0f);
    east.sun_visibility(sun_from(90, 10), vis);
    for (float v : vis) EXPECT_EQ(v, 1.0f);
    east.sun_visibility(sun_from(270, 25), vis);
    for (float v : vis) EXPECT_EQ(v, 1.0f);
}

TEST(MeshLighting, AReceiverInsideASphereIgnoresIt) {
    const std::vector<blockers::Sphere> one = {{{0, 0, 0}, 2.0}};
    const glm::dvec3 up(0, 0, 1);
    EXPECT_TRUE(blockers::sphere_contains(one[0], {0, 0, 2.0}));  // on the surface counts
    const sh::ShVec inside = blockers::self_shadow_log_sh(one, {0.5, 0, 0}, up, -1.0);
    for (double c : inside) EXPECT_EQ(c, 0.0);
    EXPECT_EQ(blockers::self_shadow_sun(one, {0.5, 0, 0}, up), 1.0);
    // Just outside, under the sphere: its cap is overhead and the sun straight up is lost.
    const sh::ShVec below = blockers::self_shadow_log_sh(one, {0, 0, -2.5}, up, -1.0);
    EXPECT_LT(sh::reconstruct(below, up), -0.5);
    EXPECT_EQ(blockers::self_shadow_sun(one, {0, 0, -2.5}, up), 0.0);
    // Two spheres: the one holding the point is ignored, the other still shadows it.
    const std::vector<blockers::Sphere> two = {{{0, 0, 0}, 2.0}, {{0, 0, 5.0}, 1.5}};
    EXPECT_EQ(blockers::self_shadow_sun(two, {0, 0, 1.0}, up), 0.0);
    EXPECT_EQ(blockers::self_shadow_sun(two, {0, 0, 1.0}, -up), 1.0);
}

// A table: a 4 x 4 m top 3 m over a 10 x 10 m floor whose four triangles meet at its centre,
// under the top. One sphere bounds it all.
TEST(MeshLighting, TheTrianglesShadowTheMeshItselfWhereItsSpheresCannot) {
    mesh::TriangleMesh table;
    auto quad = [&](double h, double z) {
        const glm::vec3 a(-h, -h, z), b(h, -h, z), c(h, h, z), d(-h, h, z);
        for (const glm::vec3& p : {a, b, c, a, c, d}) table.positions.push_back(p);
    };
    quad(2.0, 3.0);
    const glm::vec3 centre(0, 0, 0), corners[4] = {{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}};
    for (int i = 0; i < 4; ++i)
        for (const glm::vec3& p : {centre, corners[i], corners[(i + 1) % 4]}) table.positions.push_back(p);
    table.normals.assign(table.positions.size(), glm::vec3(0, 0, 1));
    table.material.assign(table.positions.size() / 3, 0);
    table.materials.resize(1);
    mesh::Placement place;
    place.height_m = 100.0;  // far above the flat ground: only the table shadows itself
    const glm::dvec2 anchor(30, 30);
    const blockers::Sphere bound{{0, 0, 1.5}, std::hypot(5.0 * std::sqrt(2.0), 1.5)};
    blockers::PlacedSpheres ps = blockers::place_spheres({&bound, 1}, place, anchor, 0.0);
    const Terrain flat(61, 61, 5.0, [](double, double) { return 0.0; });
    MeshLightingOptions o;
    o.curvature = false;
    const glm::dvec3 sun = sun_from(200, 85);
    std::vector<float> by_spheres, by_triangles;
    MeshLighting(flat.grid, place_mesh(table, place, anchor, 0.0), &ps, {}, o).sun_visibility(sun, by_spheres);
    ps.model_triangles = blockers::model_triangle_bvh(table);
    const MeshLighting lit(flat.grid, place_mesh(table, place, anchor, 0.0), &ps, {}, o);
    lit.sun_visibility(sun, by_triangles);
    const std::size_t n = lit.mesh().corners();
    ASSERT_EQ(by_triangles.size(), 2 * n);
    for (std::size_t k = 0; k < n; ++k) {
        const glm::vec3 p = table.positions[k];
        const bool top = p.z > 1.0, under_top = !top && std::abs(p.x) < 2 && std::abs(p.y) < 2;
        // Cast by the triangles: the top's upper side and the floor's open corners in the sun,
        // the floor's centre under the top and the top's underside in shade.
        EXPECT_EQ(by_triangles[k], top || !under_top ? 1.0f : 0.0f) << k;
        // Under the floor's centre the floor itself hides the sun (the corners' undersides are on
        // the plates' edges, where the disc's rays may pass beside them).
        if (p == centre) {
            EXPECT_EQ(by_triangles[n + k], 0.0f) << k;
        }
        // Every point lies inside the one sphere, which it ignores: the spheres see no shadow.
        EXPECT_EQ(by_spheres[k], 1.0f) << k;
    }
}

TEST(MeshLighting, FiveHundredOverlappingSpheresStayFiniteAndClamped) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    blockers::PlacedSpheres ps;
    ps.anchor = {30, 30};
    while (ps.spheres.size() < 500) {
        const glm::dvec3 p(u(rng), u(rng), u(rng));
        if (glm::dot(p, p) > 1.0) continue;
        ps.spheres.push_back({glm::dvec3(12.0 * p.x, 12.0 * p.y, 30.0 + 10.0 * p.z), 2.0 + 2.0 * (u(rng) + 1.0)});
    }
    ps.hierarchy = blockers::build_sphere_hierarchy(ps.spheres);
    // Receivers on and around the ball in every orientation.
    PlacedMesh m;
    m.anchor = ps.anchor;
    while (m.positions.size() < 900) {
        const glm::dvec3 p(u(rng), u(rng), u(rng));
        if (glm::dot(p, p) > 1.0) continue;
        m.positions.push_back(glm::dvec3(18.0 * p.x, 18.0 * p.y, 30.0 + 15.0 * p.z));
        m.normals.push_back(glm::vec3(glm::normalize(p)));
        if (m.positions.size() % 3 == 0) m.albedo.push_back(glm::vec3(1.0f));
    }
    const Terrain flat(61, 61, 5.0, [](double, double) { return 0.0; });
    MeshLightingOptions o;
    o.curvature = false;
    const MeshLighting lit(flat.grid, m, &ps, {}, o);
    // Visibility after exponentiation (scaling and squaring) sampled over the sphere.
    const std::size_t n = lit.receivers();
    std::vector<float> log_sh(lit.log_visibility());
    const std::vector<float> v = visibility::exp_sh_raster(log_sh, n, sh::ExpMethod::scaling_squaring, 2);
    const sh::SphereQuadrature quadrature(16, 32);
    double lo = 1e30, hi = -1e30;
    for (std::size_t r = 0; r < n; ++r) {
        sh::ShVec c{};
        for (int i = 0; i < 16; ++i) {
            c[std::size_t(i)] = v[std::size_t(i) * n + r];
            ASSERT_TRUE(std::isfinite(c[std::size_t(i)])) << r;
        }
        for (const glm::dvec3& d : quadrature.directions()) {
            const double x = sh::reconstruct(c, d);
            lo = std::min(lo, x), hi = std::max(hi, x);
            const double clamped = std::clamp(x, 0.0, 1.0);
            ASSERT_TRUE(clamped >= 0.0 && clamped <= 1.0);
        }
    }
    std::printf("500 overlapping spheres, self-shadowed receivers: visibility in [%.4f, %.4f] before clamping\n", lo,
                hi);
    EXPECT_GT(lo, -1.0);
    EXPECT_LT(hi, 2.0);
    // What the picture gets: finite, non-negative radiance and sun visibility in [0, 1].
    const UniformSky sky(sun_from(200, 40), 3.0f);
    std::vector<glm::vec3> rad;
    lit.radiance(light::project_sky_sh(sky), sky.sun(), true, rad);
    for (const glm::vec3& c : rad) ASSERT_TRUE(std::isfinite(c.x) && c.x >= 0.0f);
    std::vector<float> vis;
    lit.sun_visibility(sky.sun().direction, vis);
    for (float x : vis) ASSERT_TRUE(x >= 0.0f && x <= 1.0f);
}

TEST(MeshLighting, BelowTheTerrainItIsDarkAndOverTheEdgeItIsFinite) {
    const Terrain flat(60, 60, 5.0, [](double, double) { return 100.0; });
    const UniformSky sky(sun_from(180, 40), 3.0f);
    const light::SkySh sh = light::project_sky_sh(sky);
    MeshLightingOptions o;
    o.curvature = false;
    std::vector<glm::vec3> rad;
    const MeshLighting buried(flat.grid, tile_at({30, 30}, 60.0), nullptr, {}, o);
    buried.radiance(sh, sky.sun(), true, rad);
    for (const glm::vec3& c : rad) EXPECT_TRUE(std::isfinite(c.x) && c.x < 0.12f) << c.x;
    for (const glm::dvec2 anchor : {glm::dvec2(-2, 30), glm::dvec2(-40, -40), glm::dvec2(59.5, 59.5)}) {
        const MeshLighting edge(flat.grid, tile_at(anchor, 130.0, 8.0), nullptr, {}, o);
        edge.radiance(sh, sky.sun(), true, rad);
        // Open sky above the flat ground and its base plane: about 1 + the sun's E cos / pi.
        const double want = 1.0 + 3.0 * std::sin(radians(40.0)) / kPi;
        for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(rad[k].x, want, 0.03) << anchor.x;
        for (const glm::vec3& c : rad) EXPECT_TRUE(std::isfinite(c.x) && c.x >= 0.0f);
    }
}

TEST(MeshView, TrianglesInFrontOfTheTerrainShowAndBelowItAreHidden) {
    const Terrain flat(200, 200, 10.0, [](double, double) { return 0.0; });
    geo::GeoTransform gt;
    gt.x0 = 500000, gt.dx_col = 10, gt.y0 = 5000000, gt.dy_row = -10;
    const geo::Georef georef(200, 200, gt, geo::Crs::from_definition("EPSG:32631"), true);
    Camera cam;
    const glm::dvec2 ll = georef.pixel_to_lonlat(100.5, 180.5);
    cam.lon_deg = ll.x, cam.lat_deg = ll.y, cam.height_m = 60, cam.heading_deg = 0, cam.pitch_deg = -10,
    cam.fov_deg = 60;
    PerspectiveOptions po;
    po.width = 160, po.height = 90;
    po.curvature = false;
    const PerspectiveView view(flat.grid, georef, cam, po);
    // A 40 m wide vertical square 400 m ahead (north), 10..50 m up, facing the camera.
    auto square = [](double z0) {
        PlacedMesh m;
        m.anchor = {100, 140};
        const glm::dvec3 a(-20, 0, z0), b(20, 0, z0), c(20, 0, z0 + 40), d(-20, 0, z0 + 40);
        m.positions = {a, b, c, a, c, d};
        m.normals.assign(6, glm::vec3(0, -1, 0));
        m.albedo.assign(2, glm::vec3(1.0f));
        return m;
    };
    const PlacedMesh above = square(10.0), below = square(-60.0);
    const PlacedMesh* a[] = {&above};
    const MeshView shown(flat.grid, view, a, false);
    // 40 m at 400 m is 5.7 deg of the 60-deg field: ~15 pixels wide and high.
    EXPECT_GT(shown.covered_pixels(), 150u);
    EXPECT_LT(shown.covered_pixels(), 400u);
    EXPECT_EQ(shown.hidden_samples(), 0u);
    const PlacedMesh* b[] = {&below};
    const MeshView hidden(flat.grid, view, b, false);
    EXPECT_EQ(hidden.covered_pixels(), 0u);
    EXPECT_GT(hidden.hidden_samples(), 0u);
    // Composed: the square's pixels take its radiance (uniform 2 here), the rest stay.
    std::vector<glm::vec3> image(std::size_t(po.width) * po.height, glm::vec3(0.25f));
    const std::vector<std::vector<glm::vec3>> radiance = {std::vector<glm::vec3>(12, glm::vec3(2.0f))};
    light::SkyTable table(light::SkyGrid::whole_sphere(32, 16));
    table.update(UniformSky(sun_from(180, 40), 0.0f));
    shown.compose(radiance, table, image);
    std::size_t lit = 0;
    for (const glm::vec3& c : image) lit += c.x > 1.5f;
    EXPECT_GT(lit, 100u);
}

}  // namespace
}  // namespace ts::render
