// The streamed DEM's overview, made band by band, against the same quantities computed on the
// whole DEM in memory.
#include "core/fly/terrain_overview.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/dem/dem_source.hpp"
#include "core/dem/fill_voids.hpp"
#include "core/dem/read_dem.hpp"
#include "core/fly/detail_tile.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/terrain/height_pyramid.hpp"
#include "core/util/error.hpp"

namespace ts::fly {
namespace {

const std::string kData = TS_SHARED_DATA;

// The DEM cropped as the overview crops it.
dem::Dem cropped(const dem::Dem& d, int w, int h) {
    dem::Dem out = d;
    out.width = w, out.height = h;
    out.z.clear(), out.void_mask.clear();
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) out.z.push_back(d.at(c, r)), out.void_mask.push_back(d.void_mask[d.index(c, r)]);
    out.georef = d.georef.window(0, 0, w, h);
    return out;
}

class OverviewOf : public ::testing::TestWithParam<std::string> {};

TEST_P(OverviewOf, TheWholeDemsPointsMeanLevelErrorsAndNodes) {
    const std::string path = kData + "/dem/" + GetParam();
    const dem::DemSource source({path});
    dem::Dem whole = dem::read_dem(path);
    ASSERT_EQ(whole.void_count(), 0u) << "a DEM without voids: the overview fills its own";
    for (int level : {1, 2, 3}) {
        TerrainOverviewOptions o;
        o.level = level;
        o.far_shift = 3;
        const TerrainOverview ov = build_terrain_overview(source, o);
        const int step = 1 << level;
        EXPECT_EQ((ov.width - 1) % step, 0);
        EXPECT_GT(ov.width, whole.width - step);
        EXPECT_LE(ov.width, whole.width);
        const dem::Dem d = cropped(whole, ov.width, ov.height);
        const terrain::HeightGrid g = terrain::metric_view(d);
        // The points are the level-0 texels, georeferenced where those texels are.
        ASSERT_EQ(ov.points.width, (ov.width - 1) / step + 1);
        for (int j = 0; j < ov.points.height; ++j)
            for (int i = 0; i < ov.points.width; ++i) ASSERT_EQ(ov.points.at(i, j), d.at(i * step, j * step));
        const glm::dvec2 a = ov.points.georef.pixel_to_lonlat(3.5, 2.5), b = d.georef.pixel_to_lonlat(3 * step + 0.5, 2 * step + 0.5);
        EXPECT_NEAR(a.x, b.x, 1e-9);
        EXPECT_NEAR(a.y, b.y, 1e-9);
        // Row spacing as terrain::metric_view's.
        for (int r = 0; r < d.height; r += 37) {
            EXPECT_DOUBLE_EQ(ov.dx0_m[std::size_t(r)], g.dx_m[std::size_t(r)]);
            EXPECT_DOUBLE_EQ(ov.dy0_m[std::size_t(r)], g.dy_m[std::size_t(r)]);
        }
        // The far field's mean level, bit for bit.
        std::vector<float> m(d.z);
        int w = d.width, h = d.height;
        for (int k = 0; k < 3; ++k) {
            m = terrain::downsample_2x2(m.data(), w, h, false, 1);
            w = (w + 1) / 2, h = (h + 1) / 2;
        }
        ASSERT_EQ(ov.far_width, w);
        ASSERT_EQ(ov.far_height, h);
        ASSERT_EQ(ov.far_mean.size(), m.size());
        for (std::size_t i = 0; i < m.size(); ++i) ASSERT_EQ(ov.far_mean[i], m[i]) << i;
        // The mesh errors of the levels up to the points' from the histogram: never below the
        // exact quantile, at most one bin (2.2%) above; the maxima exact.
        CdlodOptions lod;
        const CdlodSummary exact = summarize_cdlod(g, lod);
        ASSERT_EQ(ov.cdlod.stored_level, level);
        for (int k = 1; k <= level; ++k) {
            const double e = exact.error_m[std::size_t(k)];
            EXPECT_GE(ov.cdlod.error_m[std::size_t(k)], e - 1e-6) << "level " << k;
            EXPECT_LE(ov.cdlod.error_m[std::size_t(k)], e * 1.022 + 1e-3) << "level " << k;
            EXPECT_NEAR(ov.cdlod.max_error_m[std::size_t(k)], exact.max_error_m[std::size_t(k)], 1e-3) << "level " << k;
        }
        // The stored levels' node ranges, exactly.
        ASSERT_EQ(ov.cdlod.node_z.size(), exact.node_z.size() - std::size_t(level));
        for (std::size_t k = 0; k < ov.cdlod.node_z.size(); ++k)
            ASSERT_EQ(ov.cdlod.node_z[k], exact.node_z[k + std::size_t(level)]) << "level " << k + std::size_t(level);
        EXPECT_FLOAT_EQ(float(ov.z_top), *std::max_element(d.z.begin(), d.z.end()));
    }
}

INSTANTIATE_TEST_SUITE_P(SharedDems, OverviewOf,
                         ::testing::Values("copernicus_N45E005_grenoble_500px.tif", "srtm3_N39E040_1000px.tif"));

TEST(TerrainOverview, VoidsAreFilledAndCounted) {
    const dem::DemSource source({kData + "/dem/N00E010.hgt"});
    TerrainOverviewOptions o;
    o.level = 2;
    const TerrainOverview ov = build_terrain_overview(source, o);
    const dem::Dem whole = dem::read_dem(kData + "/dem/N00E010.hgt");
    std::uint64_t voids = 0;
    for (int r = 0; r < ov.height; ++r)
        for (int c = 0; c < ov.width; ++c) voids += std::isnan(whole.at(c, r)) ? 1 : 0;
    EXPECT_EQ(ov.void_texels, voids);
    for (float z : ov.points.z) ASSERT_FALSE(std::isnan(z));
}

TEST(TerrainOverview, ADemTooSmallToStreamIsAnInputError) {
    const dem::DemSource source({kData + "/dem/nodata_3x3.tif"});
    EXPECT_THROW(build_terrain_overview(source, {}), InputError);
}

TEST(DetailTile, LayoutHoldsTheFinestStoredLevelsNodes) {
    TerrainOverview ov;
    ov.width = 4097, ov.height = 2049;
    ov.cdlod.stored_level = 3;
    DetailTileLayout l = detail_tile_layout(ov, 16);
    EXPECT_EQ(l.tile_texels, 256);
    EXPECT_EQ(l.tiles_x, 16);
    EXPECT_EQ(l.tiles_y, 8);
    // A level-2 node of 64 texels: four a tile side.
    EXPECT_EQ(tile_of_node(l, 2, 7, 3), (DetailTileKey{1, 0}));
    EXPECT_EQ(tile_of_node(l, 0, 16, 47), (DetailTileKey{1, 2}));
    ov.cdlod.stored_level = 6;
    l = detail_tile_layout(ov, 16);
    EXPECT_EQ(l.tile_texels, 512);  // one level-5 node
}

}  // namespace
}  // namespace ts::fly
