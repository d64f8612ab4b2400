// The meshes' share of --max-error (core/quality/blocker_quality.hpp) bounds what their spheres
// really do wrong against their triangles (ray-traced, core/visibility/blocker_reference.hpp) on
// a crop of a shared DEM: for the Cessna and the milk truck, enlarged to cast shadows of several
// texels, under three suns and at 8, 64 and 512 spheres, the measured sun and sky parts of the
// picture's relative radiance error are at most the predicted ones. The sun part is measured as
// the model states it: the RMS over the picture of max(0, n.s) times the sun visibility's error,
// over the picture's mean of max(0, n.s) (the direct sun alone, the largest relative share); the
// sky part as the RMS of the sky visibility's error over the picture's mean sky visibility.
// Also: the flat outline is exact for one sphere, and the choice takes the fewest spheres.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/blockers/placed_spheres.hpp"
#include "core/blockers/sphere_decomposition.hpp"
#include "core/dem/crop.hpp"
#include "core/dem/read_dem.hpp"
#include "core/geo/azimuth.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/quality/blocker_quality.hpp"
#include "core/render/blocker_sky_clamp.hpp"
#include "core/render/scene_blockers.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/visibility/blocker_footprint.hpp"
#include "core/visibility/blocker_log_sh.hpp"
#include "core/visibility/blocker_reference.hpp"
#include "core/visibility/blocker_sun_shadow.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/visibility_backend.hpp"

namespace ts {
namespace {

constexpr double kPi = 3.14159265358979323846;

glm::dvec3 sun_direction(double azimuth_deg, double elevation_deg) {
    return geo::enu_direction(geo::azimuth_cw_from_north_to_phi(azimuth_deg), elevation_deg * kPi / 180.0);
}

TEST(BlockerQuality, OneSphereCastsItsAnalyticShadowAndMatchesItself) {
    // A mesh that is a fine triangulated sphere against its own bounding sphere: both shadows are
    // the disc of radius r over sin(e), so the mismatch is only the polygon's facets.
    mesh::TriangleMesh m;
    const int n = 64;
    const double r = 3.0;
    auto at = [&](int i, int j) {
        const double th = kPi * i / n, ph = 2 * kPi * j / n;
        return glm::vec3(glm::dvec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)) * r);
    };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            for (const glm::vec3& p : {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)})
                m.positions.push_back(p), m.normals.push_back(glm::normalize(p));
            m.material.push_back(0), m.material.push_back(0);
        }
    m.materials.resize(1);
    const blockers::Sphere s{{0, 0, 0}, r};
    for (double el : {10.0, 35.0, 90.0}) {
        const quality::ShadowOutline o = quality::flat_shadow_outline(m, {&s, 1}, {}, sun_direction(200, el));
        const double want = kPi * r * r / std::sin(el * kPi / 180.0);
        EXPECT_NEAR(o.sphere_area_m2, want, 0.01 * want) << el;
        EXPECT_NEAR(o.triangle_area_m2, want, 0.01 * want) << el;
        EXPECT_LT(o.mismatch_area_m2, 0.01 * want) << el;
    }
    EXPECT_EQ(quality::flat_shadow_outline(m, {&s, 1}, {}, sun_direction(200, -3)).sphere_area_m2, 0.0);
}

TEST(BlockerQuality, TheChoiceIsTheFewestSpheresUnderTheBudget) {
    std::vector<int> asked;
    const auto error_of = [&asked](int n) {
        asked.push_back(n);
        return 1.0 / n;
    };
    const quality::SphereCountChoice c = quality::choose_sphere_count(0.02, error_of);
    EXPECT_TRUE(c.met);
    EXPECT_EQ(c.spheres, 64);
    EXPECT_EQ(asked, (std::vector<int>{8, 16, 32, 64}));
    const quality::SphereCountChoice none = quality::choose_sphere_count(1e-4, [](int n) { return 1.0 / n; });
    EXPECT_FALSE(none.met);
    EXPECT_EQ(none.spheres, 512);
}

struct MeshCase {
    const char* name;
    const char* dem;
    const char* file;
    double scale, agl, heading;
};

class BlockerMaxError : public ::testing::TestWithParam<MeshCase> {};

TEST_P(BlockerMaxError, ThePredictedShareBoundsTheSpheresErrorAgainstTheTriangles) {
    const MeshCase mc = GetParam();
    const std::string data = TS_SHARED_DATA;
    const dem::Dem full = dem::read_dem(data + "/dem/" + mc.dem);
    // 100 x 100 texels a quarter of the way in.
    const dem::Dem crop = dem::texel_window(full, full.width / 4, full.height / 4, 100, 100);
    const terrain::HeightGrid grid = terrain::metric_view(crop);
    const render::NormalField normals = render::terrain_normals(grid, 0);
    const mesh::TriangleMesh mesh = mesh::import_mesh(data + "/meshes/" + mc.file);
    mesh::Placement place;
    place.height_m = mc.agl, place.above_ground = true, place.heading_deg = mc.heading, place.scale = mc.scale;
    const glm::dvec2 anchor(grid.width / 2.0, grid.height / 2.0);
    const double ground = render::ground_height(grid, anchor);
    const double curvature = visibility::curvature_factor(true);
    const visibility::PlacedTriangles tris = visibility::place_triangles(mesh, place, anchor, ground);

    visibility::VisibilityRequest req;
    req.horizon.directions = 16;
    req.log_sh = true;
    const visibility::VisibilityResult base = visibility::make_cpu_visibility_backend()->compute(grid, req);
    const std::size_t texels = base.horizons.texels();
    const sh::ShVec lobe = visibility::zenith_cosine_lobe();
    const sh::ExpMethod exp = sh::ExpMethod::scaling_squaring;
    double picture_m2 = 0, mean_sky = 0;
    for (int r = 0; r < grid.height; ++r) picture_m2 += grid.width * grid.dx_m[std::size_t(r)] * grid.dy_m[std::size_t(r)];
    for (std::size_t t = 0; t < texels; ++t) mean_sky += visibility::sky_visibility_of_log_sh(base.log_sh.data() + t, texels, exp, lobe);
    mean_sky /= double(texels);

    visibility::ReferenceOptions ro;
    ro.sky_strata = 16, ro.sun_samples = 48;
    struct Sun {
        double az, el;
    };
    for (int count : {8, 64, 512}) {
        blockers::DecompositionOptions d;
        d.count = count;
        const blockers::SphereDecomposition dec = blockers::decompose_into_spheres(mesh, d);
        blockers::SphereBlockers b;
        b.meshes.push_back(blockers::place_spheres(dec.spheres, place, anchor, ground));
        const double min_sine = blockers::min_cap_sine(b.options.min_solid_angle_sr);

        // Sky: the reference over the footprint grown to three times its size, where the
        // triangles' faint darkening beyond the footprint is counted as our error.
        const visibility::TexelRect fp = visibility::sky_footprint(grid, b.meshes[0], min_sine);
        const int gw = fp.col1 - fp.col0, gh = fp.row1 - fp.row0;
        visibility::TexelRect wide{std::max(0, fp.col0 - gw), std::max(0, fp.row0 - gh), std::min(grid.width, fp.col1 + gw),
                                   std::min(grid.height, fp.row1 + gh)};
        const visibility::SkyReference sky_ref = visibility::reference_sky(grid, base.horizons, tris, wide, curvature, ro);
        std::vector<float> log_sh(base.log_sh.begin(), base.log_sh.end());
        visibility::add_blocker_log_sh(grid, {0, 0, grid.width, grid.height}, b, curvature, 0, log_sh.data());
        double sky_se = 0;
        const int ww = wide.col1 - wide.col0;
        for (int r = wide.row0; r < wide.row1; ++r)
            for (int c = wide.col0; c < wide.col1; ++c) {
                const std::size_t t = std::size_t(r) * std::size_t(grid.width) + std::size_t(c);
                const std::size_t k = std::size_t(r - wide.row0) * std::size_t(ww) + std::size_t(c - wide.col0);
                const double with = visibility::sky_visibility_of_log_sh(log_sh.data() + t, texels, exp, lobe);
                const double without = visibility::sky_visibility_of_log_sh(base.log_sh.data() + t, texels, exp, lobe);
                const double e = (render::blocked_sky_term(with, without) - without) -
                                 (double(sky_ref.with_mesh[k]) - double(sky_ref.terrain[k]));
                sky_se += e * e;
            }
        const double measured_sky = std::sqrt(sky_se / double(texels)) / mean_sky;
        const double texel_m2 = grid.dx_m[std::size_t(anchor.y)] * grid.dy_m[std::size_t(anchor.y)];
        const double fp_m2 = double(fp.texels()) * texel_m2;

        // The shadow cast by the spheres, and by the triangles where the spheres shadow.
        blockers::SphereBlockers by_spheres = b, by_triangles = b;
        by_spheres.options.sun_caster = blockers::SphereBlockerOptions::SunCaster::spheres;
        by_triangles.meshes[0].model_triangles = blockers::model_triangle_bvh(mesh);
        const visibility::BlockerSunShadow shadow(grid, by_spheres, curvature, 0);
        const visibility::BlockerSunShadow tri_shadow(grid, by_triangles, curvature, 0);
        for (const Sun s : {Sun{135, 30}, Sun{250, 12}, Sun{200, 60}}) {
            const glm::dvec3 dir = sun_direction(s.az, s.el);
            std::vector<float> vis(texels, 1.0f), tri_vis(texels, 1.0f);
            shadow.apply(s.az, s.el, vis);
            tri_shadow.apply(s.az, s.el, tri_vis);
            const visibility::TexelRect rect = shadow.footprint(0, s.az, s.el);
            const std::vector<float> ref = visibility::reference_sun(grid, tris, rect, dir, b.options.sun_radius_rad,
                                                                     curvature, ro);
            double cos_sum = 0, se = 0, tri_se = 0;
            for (std::size_t t = 0; t < texels; ++t)
                cos_sum += std::max(0.0, normals.x[t] * dir.x + normals.y[t] * dir.y + normals.z[t] * dir.z);
            const int rw = rect.col1 - rect.col0;
            for (int r = rect.row0; r < rect.row1; ++r)
                for (int c = rect.col0; c < rect.col1; ++c) {
                    const std::size_t t = std::size_t(r) * std::size_t(grid.width) + std::size_t(c);
                    const double lit = std::max(0.0, normals.x[t] * dir.x + normals.y[t] * dir.y + normals.z[t] * dir.z);
                    const double want = ref[std::size_t(r - rect.row0) * std::size_t(rw) + std::size_t(c - rect.col0)];
                    const double e = lit * (double(vis[t]) - want), tri_e = lit * (double(tri_vis[t]) - want);
                    se += e * e, tri_se += tri_e * tri_e;
                }
            const double mean_cos = cos_sum / double(texels);
            const double measured_sun = std::sqrt(se / double(texels)) / mean_cos;
            const double measured_tri_sun = std::sqrt(tri_se / double(texels)) / mean_cos;
            const quality::BlockerSun bs{dir, mean_cos};
            const quality::MeshErrorTerms predicted =
                quality::predicted_mesh_error(mesh, dec.spheres, place, {&bs, 1}, {picture_m2, texel_m2}, fp_m2, false);
            const quality::MeshErrorTerms tri_predicted =
                quality::predicted_mesh_error(mesh, dec.spheres, place, {&bs, 1}, {picture_m2, texel_m2}, fp_m2, true);
            std::printf("%s: %s x%g, %d spheres, sun %g/%g: sun measured %.4f predicted %.4f (cast by the triangles: "
                        "%.4f, %.4f); sky measured %.4f predicted %.4f\n",
                        mc.name, mc.file, mc.scale, count, s.az, s.el, measured_sun, predicted.sun, measured_tri_sun,
                        tri_predicted.sun, measured_sky, predicted.sky);
            EXPECT_LE(measured_sun, predicted.sun) << count << " spheres, sun " << s.az << "/" << s.el;
            EXPECT_LE(measured_tri_sun, tri_predicted.sun) << count << " spheres, sun " << s.az << "/" << s.el;
            EXPECT_LT(tri_predicted.sun, predicted.sun);
            EXPECT_LE(measured_sky, predicted.sky) << count << " spheres";
            EXPECT_GT(measured_sun, 0.1 * predicted.sun) << "the bound should not be loose by 10x";
        }
    }
}

INSTANTIATE_TEST_SUITE_P(SharedMeshes, BlockerMaxError,
                         ::testing::Values(
                             // The two cases kSkyFootprintRmse was taken from.
                             MeshCase{"GrenobleCessna", "copernicus_N45E005_grenoble_500px.tif", "c172p.ac", 120, 300, 30},
                             MeshCase{"GrenobleMilkTruck", "copernicus_N45E005_grenoble_500px.tif",
                                      "CesiumMilkTruck/CesiumMilkTruck.gltf", 150, 0, 70},
                             // Held out: other DEMs, sizes, heights and headings.
                             MeshCase{"AnatoliaCessna", "srtm3_N39E040_1000px.tif", "c172p.ac", 60, 150, 160},
                             MeshCase{"N00E010MilkTruck", "N00E010.hgt", "CesiumMilkTruck/CesiumMilkTruck.gltf", 80, 20, 10}),
                         [](const ::testing::TestParamInfo<MeshCase>& p) { return std::string(p.param.name); });

}  // namespace
}  // namespace ts
