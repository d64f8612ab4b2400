#include <cmath>

#include <gtest/gtest.h>

#include "core/dem/mosaic.hpp"
#include "core/dem/read_dem.hpp"
#include "core/util/error.hpp"

using namespace ts::dem;
namespace fs = std::filesystem;

namespace {
Dem grid(int w, int h, double x0, double y0, double cell, int epsg, float value) {
    Dem d;
    d.width = w;
    d.height = h;
    d.z.assign(std::size_t(w * h), value);
    d.void_mask.assign(d.z.size(), 0);
    d.georef = ts::geo::Georef(w, h, {x0, cell, 0, y0, 0, -cell}, ts::geo::Crs::from_epsg(epsg), true);
    d.source = "grid" + std::to_string(int(value));
    return d;
}
}  // namespace

TEST(Mosaic, NeighbouringSrtmTilesShareTheirEdgeColumn) {
    const fs::path dem = fs::path(TS_SHARED_DATA) / "dem";
    const Dem west = read_dem(dem / "N00E010.hgt");
    const Dem east = read_dem(dem / "N00E011.hgt.zip");
    const Dem m = mosaic({west, east});
    ASSERT_EQ(m.width, 2401);
    ASSERT_EQ(m.height, 1201);
    for (int r : {0, 600, 1200}) {
        EXPECT_EQ(m.at(0, r), west.at(0, r));
        EXPECT_EQ(m.at(1200, r), west.at(1200, r));
        EXPECT_EQ(m.at(2400, r), east.at(1200, r));
        EXPECT_EQ(m.at(1500, r), east.at(300, r));
    }
    const glm::dvec2 ul = m.georef.pixel_to_crs(0, 0), lr = m.georef.pixel_to_crs(2401, 1201);
    EXPECT_NEAR(ul.x, 10 - 0.5 / 1200, 1e-12);
    EXPECT_NEAR(lr.x, 12 + 0.5 / 1200, 1e-12);
    EXPECT_NEAR(lr.y, -0.5 / 1200, 1e-12);
    EXPECT_EQ(m.void_count(), 0u);
}

TEST(Mosaic, GapsBetweenPartsAreVoids) {
    const Dem m = mosaic({grid(2, 2, 0, 4, 1, 32633, 1), grid(2, 2, 3, 4, 1, 32633, 2)});
    ASSERT_EQ(m.width, 5);
    EXPECT_EQ(m.void_count(), 2u);  // column 2 is covered by neither
    EXPECT_TRUE(std::isnan(m.at(2, 0)));
    EXPECT_EQ(m.at(4, 1), 2.0f);
}

TEST(Mosaic, RefusesMismatchedGrids) {
    const Dem a = grid(2, 2, 0, 4, 1, 32633, 1);
    EXPECT_THROW(mosaic({a, grid(2, 2, 2, 4, 1, 32634, 2)}), ts::InputError);    // CRS
    EXPECT_THROW(mosaic({a, grid(2, 2, 2, 4, 2, 32633, 2)}), ts::InputError);    // resolution
    EXPECT_THROW(mosaic({a, grid(2, 2, 2.5, 4, 1, 32633, 2)}), ts::InputError);  // half-cell offset
    try {
        mosaic({a, grid(2, 2, 2, 4, 1, 32634, 2)});
    } catch (const ts::InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("grid2: ", 0), 0u) << e.what();  // names the odd one out
    }
}
