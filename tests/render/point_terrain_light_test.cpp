// The terrain's light at one point in the air (the flythrough aircraft's): the sky an upward
// normal gets from the visible sky SH at the bottom of a V valley against the analytic
// cos(beta) and against MeshLighting at the same point, and the sun lost behind a ridge.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "core/render/mesh_lighting.hpp"
#include "core/render/point_terrain_light.hpp"
#include "core/sh/sh_shared.hpp"
#include "core/util/angles.hpp"
#include "tests/render/uniform_sky.hpp"
#include "tests/support/sun_direction.hpp"

namespace ts::render {
namespace {

using testing::UniformSky;

terrain::HeightGrid make_grid(int w, int h, double spacing, std::vector<float>& z, auto f) {
    z.resize(std::size_t(w) * h);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r) * w + c] = float(f((c - w / 2) * spacing, (h / 2 - r) * spacing));
    return terrain::HeightGrid::uniform(w, h, z, spacing, spacing);
}

using ts::test::sun_from;

// What fly_aircraft.frag does: the clamped cosine turned to n against the SH, over pi.
double shaded(const light::SkySh& sh, const glm::dvec3& n) {
    const double lobe[4] = {0.886226925, 1.023326708, 0.495415912, 0.0};
    double f[16];
    sh::shared::ts_zh_rotate(lobe, n, f);
    double e = 0;
    for (int i = 0; i < 16; ++i) e += f[i] * sh[std::size_t(i)].x;
    return std::max(e, 0.0) / 3.14159265358979;
}

TEST(PointTerrainLight, AtTheBottomOfAVValleyTheSkyIsCosBetaAsMeshLightingSays) {
    const UniformSky sky(sun_from(180, 45), 0.0f);
    const light::SkySh sh = light::project_sky_sh(sky);
    PointTerrainLightOptions po;
    po.curvature = false;
    MeshLightingOptions mo;
    mo.curvature = false;
    mo.self_shadow = false;
    const double open = shaded(sh, {0, 0, 1});
    for (const double beta_deg : {0.0, 20.0, 35.0, 50.0}) {
        const double t = std::tan(radians(beta_deg));
        std::vector<float> z;
        const terrain::HeightGrid grid = make_grid(301, 301, 10.0, z, [&](double x, double) { return t * std::abs(x); });
        const PointTerrainLighting lighting(grid, po);
        const PointTerrainLight got = lighting.light({150, 150}, 0.05, sh, sky.sun().direction, 0.004654);
        const double up = shaded(got.visible_sky, {0, 0, 1});
        PlacedMesh tile;
        tile.anchor = {150, 150};
        tile.positions = {{0, 0, 0.05}, {0, 0, 0.05}, {0, 0, 0.05}};
        tile.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
        tile.albedo = {glm::vec3(1.0f)};
        const MeshLighting mesh(grid, tile, nullptr, {}, mo);
        std::vector<glm::vec3> rad;
        mesh.radiance(sh, sky.sun(), false, rad);
        const double want = std::cos(radians(beta_deg));
        std::printf("V valley beta %4.1f deg: point %.4f, mesh vertex %.4f, cos(beta) %.4f, open sky %.4f\n", beta_deg,
                    up, double(rad[0].x), want, open);
        // exp(V_log) * L_sky then the cosine vs exp(V_log + log cosine): both order-4
        // truncations. Measured: point -0.005 .. -0.043 from cos(beta), the mesh vertex
        // -0.004 .. +0.094, 0.001 .. 0.111 apart.
        EXPECT_NEAR(up, want, 0.06) << beta_deg;
        EXPECT_NEAR(up, rad[0].x, 0.13) << beta_deg;
        EXPECT_EQ(got.sun_fraction, 1.0f);  // 45 deg south, along the valley
    }
    // The walls darken it: 50 deg walls let through well under the open sky's.
    std::vector<float> z;
    const double t = std::tan(radians(50.0));
    const terrain::HeightGrid grid = make_grid(301, 301, 10.0, z, [&](double x, double) { return t * std::abs(x); });
    const PointTerrainLight deep = PointTerrainLighting(grid, po).light({150, 150}, 0.05, sh, sky.sun().direction, 0.004654);
    EXPECT_LT(shaded(deep.visible_sky, {0, 0, 1}), 0.75 * open);
}

TEST(PointTerrainLight, BehindARidgeThePointLosesTheSunAndInFrontKeepsIt) {
    std::vector<float> z;
    const terrain::HeightGrid ridge =
        make_grid(201, 201, 20.0, z, [](double x, double) { return std::max(0.0, 300.0 - std::abs(x)); });
    PointTerrainLightOptions o;
    o.curvature = false;
    const PointTerrainLighting lighting(ridge, o);
    const light::SkySh sh = light::project_sky_sh(UniformSky(sun_from(270, 10), 0.0f));
    // The crest is 17 deg up from there.
    EXPECT_EQ(lighting.light({140, 100}, 50.0, sh, sun_from(270, 10), 0.004654).sun_fraction, 0.0f);
    EXPECT_EQ(lighting.light({140, 100}, 50.0, sh, sun_from(90, 10), 0.004654).sun_fraction, 1.0f);
    EXPECT_EQ(lighting.light({140, 100}, 50.0, sh, sun_from(270, 25), 0.004654).sun_fraction, 1.0f);
    // High above the crest the sky is open again: brighter than beside the ridge's foot.
    const double foot = shaded(lighting.light({116, 100}, 5.0, sh, sun_from(270, 10), 0.004654).visible_sky, {0, 0, 1});
    const double high = shaded(lighting.light({116, 100}, 3000.0, sh, sun_from(270, 10), 0.004654).visible_sky, {0, 0, 1});
    EXPECT_LT(foot, 0.9 * high);
}

}  // namespace
}  // namespace ts::render
