// The reflected light from the terrain a texel sees (terrain_reflection.hpp): an open plain, the
// foot of a wall of known G, a valley lit on one side, and the isotropic limit.
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/solar/insolation_map.hpp"
#include "core/solar/insolation_model.hpp"
#include "core/solar/terrain_reflection.hpp"
#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "core/visibility/compute_horizons.hpp"

namespace ts::solar {
namespace {

constexpr double kSpacing = 30.0;  // metres
constexpr double kAlbedo = 0.2;

// A synthetic DEM with its horizons (no curvature, as the gather's inputs say), up normals
// unless given, and each texel's tilted sky view factor over the D horizon azimuths.
struct Scene {
    int width, height;
    std::vector<float> z;
    terrain::HeightGrid grid;
    visibility::HorizonSet horizons;
    render::NormalField normals;
    std::vector<float> svf;

    Scene(int w, int h, std::vector<float> heights, bool terrain_normals_from_grid = false)
        : width(w), height(h), z(std::move(heights)) {
        grid = terrain::HeightGrid::uniform(w, h, z, kSpacing, kSpacing);
        visibility::HorizonOptions ho;
        ho.directions = 64;
        ho.curvature = false;
        horizons = visibility::compute_horizons(grid, ho);
        const std::size_t n = std::size_t(w) * std::size_t(h);
        if (terrain_normals_from_grid) {
            normals = render::terrain_normals(grid);
        } else {
            normals.x.assign(n, 0.0f), normals.y.assign(n, 0.0f), normals.z.assign(n, 1.0f);
        }
        svf.resize(n);
        std::vector<float> hz(std::size_t(ho.directions));
        for (std::size_t t = 0; t < n; ++t) {
            for (int d = 0; d < ho.directions; ++d) hz[std::size_t(d)] = horizons.angle[std::size_t(d) * n + t];
            svf[t] = float(tilted_sky_view_factor(hz.data(), ho.directions,
                                                  glm::dvec3(normals.x[t], normals.y[t], normals.z[t]), 1));
        }
    }
    std::size_t at(int c, int r) const { return std::size_t(r) * std::size_t(width) + std::size_t(c); }

    // One period: G per texel, and the isotropic estimate albedo x open x (1 - svf).
    ReflectionInputs inputs(const std::vector<float>& global, std::vector<float>& iso, double open) const {
        iso.resize(svf.size());
        for (std::size_t t = 0; t < svf.size(); ++t) iso[t] = float(kAlbedo * open * (1 - svf[t]));
        ReflectionInputs in;
        in.grid = &grid;
        in.horizons = &horizons;
        in.normals = &normals;
        in.periods = 1;
        in.global = global;
        in.isotropic_reflected = iso;
        in.svf = svf;
        in.albedo = kAlbedo;
        in.curvature = 0;
        return in;
    }
};

// One month of sun at 45 N for the whole-pipeline cases (a 10-minute step: fast enough).
InsolationModel march_at_45n(float z_max) {
    InsolationSettings s;
    s.periods = make_periods({2023, 3, 1}, {2023, 3, 31}, PeriodSplit::year, 0.0);
    s.step_minutes = 10;
    s.azimuth_bins = 4 * 64;
    s.svf_stride = 4;
    s.albedo = kAlbedo;
    return InsolationModel(s, 45.0, 45.0, 0.05, 0.0, z_max, 1000.0);
}

// (1) Open flat ground sees no terrain: nothing is reflected to it, and the global is beam plus
// diffuse.
TEST(TerrainReflection, OpenFlatPlaneGetsNothing) {
    const int w = 48, h = 40;
    Scene s(w, h, std::vector<float>(std::size_t(w) * h, 100.0f));
    visibility::HorizonOptions ho;
    ho.directions = 64;
    const visibility::HorizonSet horizons = visibility::compute_horizons(s.grid, ho);  // with curvature, as a DEM's
    const InsolationModel model = march_at_45n(100.0f);
    const std::vector<float> lat(s.z.size(), 45.0f);
    InsolationMap map = integrate_insolation(model, s.grid, horizons, s.normals, lat);
    apply_terrain_reflection(map, s.grid, horizons, s.normals, kAlbedo, TerrainReflectionSettings{}, 1);
    for (std::size_t t = 0; t < s.z.size(); ++t) {
        EXPECT_EQ(map.band(0, kReflected)[t], 0.0f) << t;
        EXPECT_FLOAT_EQ(map.band(0, kGlobal)[t], map.band(0, kBeam)[t] + map.band(0, kDiffuse)[t]) << t;
    }
}

// (2) At the foot of a long straight slope (45 degrees, from column 99 to 110, a plateau
// beyond) with G set by hand: the receiver at its foot sees the slope and nothing else (its
// floor is its own plane, the plateau hides behind the slope's top), so it gets albedo x
// G(slope) x (1 - svf), whatever the floor, the plateau and the isotropic ground get. Along any
// azimuth the slope rises at a constant angle from the receiver, so the march's first sample
// on it is the exact horizon: nothing is left to the far field and the result is exact to
// float rounding (1e-5). Before the scaling, the 16 sectors' weights sum to pi (1 - svf) of the
// 64 horizon azimuths up to the sector discretisation: both are equal-step sums over azimuth of
// the blocked weight, cos^2(phi) / (2 (1 + cos^2(phi))) on the slope's side, smooth enough for
// 16 steps to agree with 64 to 1e-5 (measured); checked at 1%.
TEST(TerrainReflection, FootOfASlopeSeesTheSlopesLight) {
    const int w = 200, h = 120, foot = 99, top = 110;
    std::vector<float> z(std::size_t(w) * h, 0.0f);
    for (int r = 0; r < h; ++r)
        for (int c = foot; c < w; ++c) z[std::size_t(r) * w + c] = float(kSpacing * (std::min(c, top) - foot));
    Scene s(w, h, std::move(z));
    const float g_slope = 2000.0f, g_floor = 500.0f, g_plateau = 3000.0f;
    std::vector<float> global(s.z.size(), g_floor), iso;
    for (int r = 0; r < h; ++r)
        for (int c = foot; c < w; ++c) global[s.at(c, r)] = c <= top ? g_slope : g_plateau;
    const ReflectionInputs in = s.inputs(global, iso, 800.0);
    const int rc = foot, rr = h / 2;
    const std::size_t t = s.at(rc, rr);
    const double blocked = 1 - s.svf[t];
    ASSERT_GT(blocked, 0.1);

    const TexelGather tg = gather_texel(in, TerrainReflectionSettings{}, rc, rr);
    EXPECT_LT(tg.far_weight, 1e-4 * tg.seen_weight);
    EXPECT_NEAR(tg.seen[0] / tg.seen_weight, g_slope, 1e-3);
    std::printf("foot of the slope: 1 - svf %.4f, gathered weight / pi (1 - svf) %.5f\n", blocked,
                (tg.seen_weight + tg.far_weight) / (kPi * blocked));
    EXPECT_NEAR((tg.seen_weight + tg.far_weight) / (kPi * blocked), 1.0, 0.01);

    const std::vector<float> reflected = gather_terrain_reflection(in, TerrainReflectionSettings{}, 1);
    EXPECT_NEAR(reflected[t], kAlbedo * g_slope * blocked, 1e-5 * kAlbedo * g_slope * blocked);
}

// An east-west V valley (rows rising 15 m each side of its axis up to 300 m, row 0 north) with
// its horizons (Earth curvature as a job has it) and the first pass of a March at 45 N.
struct ValleyCase {
    static constexpr int kWidth = 160, kHeight = 80, kAxis = 40, kHalf = 20;
    static constexpr float kRise = 0.5f * float(kSpacing);  // metres per row
    Scene scene;
    visibility::HorizonSet horizons;
    InsolationMap first;

    ValleyCase() : scene(kWidth, kHeight, heights(), true) {
        visibility::HorizonOptions ho;
        ho.directions = 64;
        horizons = visibility::compute_horizons(scene.grid, ho);
        const std::vector<float> lat(scene.z.size(), 45.0f);
        first = integrate_insolation(march_at_45n(kRise * kHalf), scene.grid, horizons, scene.normals, lat);
    }
    static std::vector<float> heights() {
        std::vector<float> z(std::size_t(kWidth) * kHeight);
        for (int r = 0; r < kHeight; ++r)
            for (int c = 0; c < kWidth; ++c)
                z[std::size_t(r) * kWidth + std::size_t(c)] = kRise * float(std::min(std::abs(r - kAxis), kHalf));
        return z;
    }
};

// (3) A V valley along the east-west axis (slopes of 26.6 degrees, 20 texels each way up to
// plateaus) under March's sun at 45 N (noon at ~40 degrees, from the south), whole pipeline:
// a texel 8 texels up the north-facing slope (a third of the sunny slope's G) sees only the
// sunny south-facing slope (its own slope is its tangent plane, the plateau hides behind the
// ridge), so it gets about albedo x G(sunny slope) x (1 - svf), G taken across the valley.
// Within 6%: the vertex texels on the valley's axis get less than the slope (25% less), and the
// sunny slope seen along the 22.5-degree sectors lies beyond the 64-texel radius, where it
// counts as open ground (also 25% below the slope); measured 2.6% low. Today's isotropic
// ground, open flat G, is 25% below the sunny slope's: the gather gets 30% more.
TEST(TerrainReflection, NorthFacingSlopeOfAValleySeesTheSunnySlope) {
    const ValleyCase v;
    const Scene& s = v.scene;
    const InsolationMap& isotropic = v.first;
    InsolationMap map = v.first;
    apply_terrain_reflection(map, s.grid, v.horizons, s.normals, kAlbedo, TerrainReflectionSettings{}, 1);

    const std::size_t t = s.at(v.kWidth / 2, v.kAxis + 8);  // row 0 is north
    const double g_sunny = isotropic.band(0, kGlobal)[s.at(v.kWidth / 2, v.kAxis - 8)];
    const double expected = kAlbedo * g_sunny * (1 - map.svf[t]);
    const double got = map.band(0, kReflected)[t], before = isotropic.band(0, kReflected)[t];
    std::printf("valley: north-facing slope reflected %.4f kWh/m2, albedo G(sunny) (1 - svf) %.4f, isotropic %.4f\n", got,
                expected, before);
    EXPECT_NEAR(got / expected, 1.0, 0.06);
    EXPECT_GT(got, 1.2 * before);
    EXPECT_FLOAT_EQ(map.band(0, kGlobal)[t],
                    float(double(map.band(0, kBeam)[t]) + map.band(0, kDiffuse)[t] + map.band(0, kReflected)[t]));
}

// Texel albedos (land cover): the shaded slope under forest (0.1) faces a snowy sunny slope
// (0.8). Its reflected light follows the albedo of what it sees, ~4x the uniform 0.2's, not
// its own (0.5x); the part left to the isotropic ground (beyond the radius) takes its own.
TEST(TerrainReflection, SeenTerrainReflectsWithItsOwnAlbedo) {
    const ValleyCase v;
    const Scene& s = v.scene;
    const InsolationMap& first = v.first;
    std::vector<float> albedo(s.z.size());
    for (int r = 0; r < v.kHeight; ++r)
        for (int c = 0; c < v.kWidth; ++c)
            albedo[s.at(c, r)] = r < v.kAxis ? 0.8f : 0.1f;  // row 0 is north: the sunny side
    InsolationMap uniform = first, cover = first;
    apply_terrain_reflection(uniform, s.grid, v.horizons, s.normals, kAlbedo, TerrainReflectionSettings{}, 1);
    apply_terrain_reflection(cover, s.grid, v.horizons, s.normals, kAlbedo, TerrainReflectionSettings{}, 1, albedo);
    const std::size_t t = s.at(v.kWidth / 2, v.kAxis + 8);
    const double ratio = cover.band(0, kReflected)[t] / uniform.band(0, kReflected)[t];
    std::printf("shaded forest slope facing snow: reflected %.2fx the uniform albedo's\n", ratio);
    EXPECT_GT(ratio, 3.0);
    EXPECT_LT(ratio, 4.0 * 1.02);
    EXPECT_FLOAT_EQ(cover.band(0, kGlobal)[t],
                    float(double(cover.band(0, kBeam)[t]) + cover.band(0, kDiffuse)[t] + cover.band(0, kReflected)[t]));
    // The gather off: the isotropic ground with the receiver's own albedo.
    TerrainReflectionSettings off;
    off.directions = 0;
    InsolationMap own = first;
    apply_terrain_reflection(own, s.grid, v.horizons, s.normals, kAlbedo, off, 1, albedo);
    EXPECT_NEAR(own.band(0, kReflected)[t] / first.band(0, kReflected)[t], 0.5, 1e-5);
}

// (4) When every texel's G is the open flat ground's, the gather gives the isotropic estimate
// back, whether the terrain is seen within the radius or left to the far field beyond it
// (a short radius on rough terrain).
TEST(TerrainReflection, TerrainLitLikeOpenGroundGivesTheIsotropicEstimate) {
    const int w = 96, h = 96;
    std::vector<float> z(std::size_t(w) * h);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c)
            z[std::size_t(r) * w + c] = float(200 * std::sin(c * 0.11) * std::cos(r * 0.07) + 40 * std::sin(c * 0.5 + r * 0.3));
    Scene s(w, h, std::move(z), true);
    const double open = 900.0;
    const std::vector<float> global(s.z.size(), float(open));
    std::vector<float> iso;
    const ReflectionInputs in = s.inputs(global, iso, open);
    for (double radius : {4.0, 64.0}) {
        TerrainReflectionSettings rs;
        rs.radius_texels = radius;
        const std::vector<float> reflected = gather_terrain_reflection(in, rs, 2);
        double far_share = 0;
        int n = 0;
        for (int r = 8; r < h - 8; r += 4)
            for (int c = 8; c < w - 8; c += 4) {
                const std::size_t t = s.at(c, r);
                EXPECT_NEAR(reflected[t], iso[t], 2e-6 * open) << c << "," << r << " radius " << radius;
                const TexelGather tg = gather_texel(in, rs, c, r);
                if (tg.seen_weight + tg.far_weight > 0) far_share += tg.far_weight / (tg.seen_weight + tg.far_weight), ++n;
            }
        std::printf("radius %.0f: mean far-field share of the blocked hemisphere %.3f\n", radius, far_share / n);
        if (radius == 4.0) {
            EXPECT_GT(far_share / n, 0.2);  // the case does exercise the fallback
        }
    }
}

// Void heights next to a receiver are skipped; void receivers stay NaN; the settings are checked.
TEST(TerrainReflection, VoidsAreSkippedAndSettingsChecked) {
    const int w = 40, h = 40;
    std::vector<float> z(std::size_t(w) * h);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r) * w + c] = float(10 * c);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    z[std::size_t(20) * w + 22] = nan;
    Scene s(w, h, std::move(z));
    std::vector<float> global(s.z.size(), 1000.0f), iso;
    global[s.at(22, 20)] = nan;
    const ReflectionInputs in = s.inputs(global, iso, 700.0);
    const std::vector<float> reflected = gather_terrain_reflection(in, TerrainReflectionSettings{}, 1);
    EXPECT_TRUE(std::isnan(reflected[s.at(22, 20)]));
    EXPECT_TRUE(std::isfinite(reflected[s.at(21, 20)]));
    EXPECT_GT(reflected[s.at(21, 20)], 0.0f);
    TerrainReflectionSettings bad;
    bad.growth = 1.0;
    EXPECT_THROW(check_reflection_settings(bad), InputError);
    bad = {};
    bad.directions = -1;
    EXPECT_THROW(check_reflection_settings(bad), InputError);
    bad = {};
    bad.directions = 0;
    EXPECT_NO_THROW(check_reflection_settings(bad));
    // Off: the isotropic estimate as it is.
    const std::vector<float> off = gather_terrain_reflection(in, bad, 1);
    EXPECT_EQ(off[s.at(5, 5)], iso[s.at(5, 5)]);
}

}  // namespace
}  // namespace ts::solar
