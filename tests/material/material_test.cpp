#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/material/material.hpp"
#include "core/util/angles.hpp"

namespace ts::render {
namespace {

struct Flat {
    std::vector<float> z;
    terrain::HeightGrid grid;
    NormalField normals;
    Flat(int w, int h, float height) : z(std::size_t(w * h), height) {
        grid = terrain::HeightGrid::uniform(w, h, z, 30, 30);
        normals = terrain_normals(grid);
    }
};

TEST(Material, RuleByHeight) {
    const MaterialRule rule;
    for (auto [height, expected] : {std::pair{300.0f, Surface::grassland}, std::pair{2200.0f, Surface::grassland},
                                    std::pair{2700.0f, Surface::rock}, std::pair{3300.0f, Surface::snow_ice}}) {
        Flat f(3, 3, height);
        const MaterialRaster m = rule_materials(f.grid, f.normals, rule);
        EXPECT_EQ(m.surface[4], expected) << height;
        EXPECT_EQ(m.water[4], 0);
    }
}

TEST(Material, SteepSlopesAreRockAndForestBelowTheTreeline) {
    // A plane at 45 degrees: rock; at 20 degrees around 1000 m: forest.
    for (auto [slope, expected] : {std::pair{45.0, Surface::rock}, std::pair{20.0, Surface::tree_cover}}) {
        std::vector<float> z(25);
        for (int r = 0; r < 5; ++r)
            for (int c = 0; c < 5; ++c) z[r * 5 + c] = float(1000 + std::tan(radians(slope)) * 30 * c);
        const auto g = terrain::HeightGrid::uniform(5, 5, z, 30, 30);
        const MaterialRaster m = rule_materials(g, terrain_normals(g));
        EXPECT_EQ(m.surface[12], expected) << slope;
    }
}

TEST(Material, WaterIsVoidOrFlatSeaLevel) {
    Flat f(3, 3, 0.0f);
    std::vector<std::uint8_t> voids(9, 0);
    const MaterialRaster sea = rule_materials(f.grid, f.normals);
    EXPECT_EQ(sea.water[4], 1);
    EXPECT_EQ(sea.surface[4], Surface::water);
    Flat land(3, 3, 5.0f);
    voids[4] = 1;
    land.grid.void_mask = voids;
    const MaterialRaster m = rule_materials(land.grid, land.normals);
    EXPECT_EQ(m.water[4], 1);   // the void
    EXPECT_EQ(m.water[0], 0);   // land at 5 m
    // A slope below sea level (a depression's flank) is not water.
    EXPECT_FALSE(is_water(false, -5.0f, 0.9f, MaterialRule{}));
}

TEST(Material, WorldCoverCodesAndOrthophoto) {
    Flat f(2, 1, 500.0f);
    const std::vector<std::uint8_t> codes = {70, 80};
    MaterialRaster m = landcover_materials(f.grid, f.normals, codes);
    EXPECT_EQ(m.surface[0], Surface::snow_ice);
    EXPECT_GT(m.ks[0], 0.0f);
    EXPECT_EQ(m.water[1], 1);
    apply_albedo(m, {glm::vec3(0.3f, 0.2f, 0.1f), glm::vec3(0.5f)});
    EXPECT_FLOAT_EQ(m.albedo_r[0], 0.3f);
    EXPECT_FLOAT_EQ(m.albedo_b[0], 0.1f);
    EXPECT_FLOAT_EQ(m.albedo_r[1], kWaterAlbedo);  // water keeps its own body colour
    Surface s{};
    EXPECT_FALSE(surface_from_worldcover(0, s));
    EXPECT_FALSE(surface_from_worldcover(11, s));
}

}  // namespace
}  // namespace ts::render

namespace ts::render {
namespace {

MaterialRaster one_texel_each(const std::vector<glm::vec3>& albedos, const std::vector<std::uint8_t>& water) {
    MaterialRaster m;
    for (std::size_t i = 0; i < albedos.size(); ++i) {
        m.albedo_r.push_back(albedos[i].x), m.albedo_g.push_back(albedos[i].y), m.albedo_b.push_back(albedos[i].z);
        m.ks.push_back(0), m.alpha.push_back(1), m.water.push_back(water[i]), m.surface.push_back(Surface::grassland);
    }
    return m;
}

double lum(const MaterialRaster& m, std::size_t i) {
    return 0.2126 * m.albedo_r[i] + 0.7152 * m.albedo_g[i] + 0.0722 * m.albedo_b[i];
}

// L' = L0^(1-c) L^c, and the tint (RGB / L) pulled by the same share towards one land tint, so
// at c = 0 every land texel has the same colour; 1 changes nothing; snow and water keep theirs.
TEST(AlbedoContrast, PullsLandLuminanceTowardsTheReferenceInLogSpace) {
    const std::vector<glm::vec3> albedos = {{0.035f, 0.060f, 0.028f}, {0.130f, 0.125f, 0.075f},
                                            {0.8f, 0.83f, 0.88f}, {0.02f, 0.02f, 0.02f}};
    const MaterialRaster before = one_texel_each(albedos, {0, 0, 0, 1});
    MaterialRaster m = before;
    compress_albedo_contrast(m, 1.0);
    EXPECT_EQ(m.albedo_g, before.albedo_g);
    for (double c : {0.0, 0.25, 0.5}) {
        m = before;
        compress_albedo_contrast(m, c);
        for (std::size_t i : {std::size_t(0), std::size_t(1)}) {
            const double want = std::pow(kAlbedoReferenceLuminance, 1 - c) * std::pow(lum(before, i), c);
            EXPECT_NEAR(lum(m, i), want, 1e-6) << c << " " << i;
        }
        // The two tints differ c times as much as before (per channel of RGB / L).
        auto tint = [](const MaterialRaster& r, std::size_t i) {
            return glm::dvec3(r.albedo_r[i], r.albedo_g[i], r.albedo_b[i]) / lum(r, i);
        };
        const glm::dvec3 d0 = tint(before, 1) - tint(before, 0), d = tint(m, 1) - tint(m, 0);
        for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(d[ch], c * d0[ch], 1e-5) << c << " " << ch;
        EXPECT_FLOAT_EQ(m.albedo_g[2], before.albedo_g[2]);  // snow
        EXPECT_FLOAT_EQ(m.albedo_g[3], before.albedo_g[3]);  // water
    }
    // The forest/fields ratio, 2.5 physically, is its square root at c = 0.5.
    m = before;
    compress_albedo_contrast(m, 0.5);
    EXPECT_NEAR(lum(m, 1) / lum(m, 0), std::sqrt(lum(before, 1) / lum(before, 0)), 1e-5);
}

}  // namespace
}  // namespace ts::render
