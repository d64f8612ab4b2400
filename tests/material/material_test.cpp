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
