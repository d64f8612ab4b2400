// Mesh blockers in the shading, end to end on small flat grids: the sky darkening under a
// sphere against the cap it hides, only the footprints changed, many overlapping spheres kept
// finite, placements below the terrain and off the grid.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/geo/crs.hpp"
#include "core/render/frame_renderer.hpp"
#include "core/render/scene_blockers.hpp"
#include "core/sh/sh_basis.hpp"
#include "core/sh/sphere_quadrature.hpp"
#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "core/visibility/blocker_footprint.hpp"
#include "core/visibility/blocker_sun_shadow.hpp"
#include "core/visibility/visibility_backend.hpp"
#include "tests/render/grey_materials.hpp"
#include "tests/render/frame_stack.hpp"
#include "tests/render/uniform_sky.hpp"

namespace ts::render {
namespace {

// Uniform radiance over the upper hemisphere and a sun disc of the given irradiance.
using testing::UniformSky;

struct Flat {
    int w, h;
    std::vector<float> z;
    terrain::HeightGrid grid;
    Flat(int w_, int h_, double spacing, float height) : w(w_), h(h_), z(std::size_t(w_) * h_, height) {
        grid = terrain::HeightGrid::uniform(w, h, z, spacing, spacing);
    }
    MaterialRaster grey() const { return testing::grey_materials(grid, 0.3f); }
};

RendererOptions options_with(const blockers::SphereBlockers* b) {
    RendererOptions o;
    o.directions = 16;
    o.curvature = false;
    o.threads = 2;
    o.blockers = b;
    return o;
}

blockers::SphereBlockers blockers_of(glm::dvec2 anchor, std::vector<blockers::Sphere> spheres) {
    blockers::SphereBlockers b;
    blockers::PlacedSpheres p;
    p.anchor = anchor;
    p.spheres = std::move(spheres);
    p.hierarchy = blockers::build_sphere_hierarchy(p.spheres);
    b.meshes.push_back(std::move(p));
    return b;
}

std::vector<glm::vec3> render_frame(const Flat& f, const blockers::SphereBlockers* b, const SunState& sun,
                                    float sun_irradiance) {
    testing::FrameStack stack(f.grid, f.grey(), terrain_normals(f.grid), {}, options_with(b));
    const UniformSky sky(sun_direction(sun), sun_irradiance);
    std::vector<glm::vec3> out;
    stack->render(sky, sun, out);
    return out;
}

// Up to a cap of 40 degrees (a receiver 1.6 radii from the centre) the order-4 log-SH cap with
// floor -1 gives the diffuse ratio within 0.033 of the opaque cap (measured: -0.009, -0.025,
// -0.033, +0.026 at 8, 15, 25, 40 degrees). Larger caps come out too light (60 degrees: +0.20):
// order 4 cannot hold a cap that wide and sharp (docs/blockers.md).
constexpr double kSkyDarkeningTolerance = 0.035;

// Under a sphere seen at the zenith with half-angle theta_b an opaque sphere hides sin^2 theta_b
// of the cosine-weighted sky: a uniform sky's diffuse light falls to 1 - sin^2 theta_b.
TEST(MeshShadows, SkyDarkeningUnderASphereFollowsTheCapItHides) {
    const Flat f(161, 161, 2.0, 0.0f);
    const SunState sun{180.0, 40.0};
    const std::vector<glm::vec3> open = render_frame(f, nullptr, sun, 0.0f);
    const std::size_t centre = f.grid.index(80, 80);
    double worst = 0;
    for (const double theta_deg : {8.0, 15.0, 25.0, 40.0, 60.0}) {
        const double r = 10.0, height = r / std::sin(radians(theta_deg));
        const blockers::SphereBlockers b = blockers_of({80, 80}, {{{0.0, 0.0, height}, r}});
        const std::vector<glm::vec3> got = render_frame(f, &b, sun, 0.0f);
        const double ratio = double(got[centre].x) / double(open[centre].x);
        const double s = std::sin(radians(theta_deg));
        const double analytic = 1.0 - s * s;
        std::printf("sky under a sphere, theta_b %4.1f deg: diffuse ratio %.4f, analytic (opaque cap) %.4f, error %+.4f\n",
                    theta_deg, ratio, analytic, ratio - analytic);
        if (theta_deg <= 40.0) worst = std::max(worst, std::abs(ratio - analytic));
        EXPECT_LT(ratio, 1.0);
    }
    EXPECT_LT(worst, kSkyDarkeningTolerance);
}

TEST(MeshShadows, OnlyTheFootprintsChange) {
    const Flat f(150, 120, 10.0, 50.0f);
    const SunState sun{220.0, 25.0};
    const blockers::SphereBlockers b =
        blockers_of({70, 60}, {{{0.0, 0.0, 80.0}, 6.0}, {{8.0, 3.0, 85.0}, 5.0}, {{-9.0, -2.0, 78.0}, 4.0}});
    const std::vector<glm::vec3> open = render_frame(f, nullptr, sun, 3.0f);
    const std::vector<glm::vec3> got = render_frame(f, &b, sun, 3.0f);
    const visibility::TexelRect sky =
        visibility::sky_footprint(f.grid, b.meshes[0], blockers::min_cap_sine(b.options.min_solid_angle_sr));
    const visibility::TexelRect sun_rect =
        visibility::BlockerSunShadow(f.grid, b, 0.0, 1).footprint(0, sun.azimuth_deg, sun.elevation_deg);
    long long changed = 0, outside = 0;
    for (int r = 0; r < f.h; ++r)
        for (int c = 0; c < f.w; ++c) {
            const std::size_t t = f.grid.index(c, r);
            const bool same = std::memcmp(&open[t], &got[t], sizeof(glm::vec3)) == 0;
            changed += !same;
            if (!sky.contains(c, r) && !sun_rect.contains(c, r)) {
                ++outside;
                ASSERT_TRUE(same) << c << "," << r;
            }
        }
    std::printf("footprints: %lld texels changed, %lld outside both rectangles bit-identical\n", changed, outside);
    EXPECT_GT(changed, 0);
    EXPECT_GT(outside, 0);
}

TEST(MeshShadows, FiveHundredOverlappingSpheresStayFinite) {
    const Flat f(48, 48, 2.0, 0.0f);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<blockers::Sphere> spheres;
    while (spheres.size() < 500) {
        const glm::dvec3 p(u(rng), u(rng), u(rng));
        if (glm::dot(p, p) > 1.0) continue;
        // A ball of 500 spheres 20 m across standing on the ground, some sunk into it.
        spheres.push_back({glm::dvec3(12.0 * p.x, 12.0 * p.y, 10.0 + 10.0 * p.z), 2.0 + 2.0 * (u(rng) + 1.0)});
    }
    const blockers::SphereBlockers b = blockers_of({24, 24}, spheres);
    visibility::VisibilityRequest req;
    req.horizon.directions = 16;
    req.horizon.curvature = false;
    req.log_sh = true;
    req.blockers = &b;
    const visibility::VisibilityResult res = visibility::make_cpu_visibility_backend()->compute(f.grid, req);
    const std::size_t texels = f.grid.z.size();
    const std::vector<float> v = visibility::exp_sh_raster(res.log_sh, texels, sh::ExpMethod::scaling_squaring, 2);
    const sh::SphereQuadrature quadrature(20, 40);
    const std::vector<glm::dvec3>& dirs = quadrature.directions();
    double lo = 1e30, hi = -1e30;
    for (std::size_t t = 0; t < texels; ++t) {
        sh::ShVec c{};
        for (int i = 0; i < 16; ++i) {
            c[std::size_t(i)] = v[std::size_t(i) * texels + t];
            ASSERT_TRUE(std::isfinite(c[std::size_t(i)])) << t;
        }
        for (const glm::dvec3& d : dirs) {
            const double x = sh::reconstruct(c, d);
            lo = std::min(lo, x), hi = std::max(hi, x);
            const double clamped = std::clamp(x, 0.0, 1.0);
            ASSERT_TRUE(clamped >= 0.0 && clamped <= 1.0);
        }
    }
    std::printf("500 overlapping spheres: visibility after exponentiation in [%.4f, %.4f] before clamping\n", lo, hi);
    // Measured [-0.39, 1.78] (scaling and squaring; SH ringing of 500 caps summed), reported in
    // docs/blockers.md; these bounds catch a blow-up, not the ringing.
    EXPECT_GT(lo, -1.0);
    EXPECT_LT(hi, 2.0);
}

TEST(MeshShadows, MeshBelowTheTerrainWarnsAndOffTheGridIsAnInputError) {
    const Flat f(100, 100, 30.0, 500.0f);
    geo::GeoTransform gt;
    gt.x0 = 500000, gt.dx_col = 30, gt.y0 = 5000000, gt.dy_row = -30;
    const geo::Georef georef(100, 100, gt, geo::Crs::from_definition("EPSG:32631"), true);
    const glm::dvec2 centre = georef.pixel_to_lonlat(50, 50);
    SceneMesh m;
    m.name = "cube.stl";
    m.placement.lon_deg = centre.x, m.placement.lat_deg = centre.y, m.placement.height_m = 100.0;
    m.model_spheres = {{{0, 0, 0}, 5.0}};
    std::vector<std::string> warnings;
    const blockers::SphereBlockers b = place_scene_meshes({&m, 1}, f.grid, georef, {}, warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("below the terrain"), std::string::npos) << warnings[0];
    // It renders: the texels inside it are dark, nothing is NaN.
    const std::vector<glm::vec3> got = render_frame(f, &b, {180, 30}, 3.0f);
    for (const glm::vec3& c : got) ASSERT_TRUE(std::isfinite(c.x));
    // agl puts it above the ground: no warning.
    m.placement.height_m = 10.0, m.placement.above_ground = true;
    warnings.clear();
    const blockers::SphereBlockers above = place_scene_meshes({&m, 1}, f.grid, georef, {}, warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_NEAR(above.meshes[0].spheres[0].center.z, 510.0, 1e-9);
    const glm::dvec2 far = georef.pixel_to_lonlat(-20, 50);
    m.placement.lon_deg = far.x, m.placement.lat_deg = far.y;
    EXPECT_THROW(place_scene_meshes({&m, 1}, f.grid, georef, {}, warnings), InputError);
}

TEST(MeshShadows, MeshOverTheGridEdgeAndBeyondIsClipped) {
    const Flat f(60, 60, 5.0, 0.0f);
    for (const glm::dvec2 anchor : {glm::dvec2(-2, 30), glm::dvec2(-40, -40), glm::dvec2(59.5, 59.5)}) {
        const blockers::SphereBlockers b = blockers_of(anchor, {{{0.0, 0.0, 30.0}, 20.0}, {{10.0, 0.0, 25.0}, 15.0}});
        const std::vector<glm::vec3> got = render_frame(f, &b, {300, 15}, 3.0f);
        for (const glm::vec3& c : got) ASSERT_TRUE(std::isfinite(c.x) && c.x >= 0.0f);
    }
}

}  // namespace
}  // namespace ts::render
