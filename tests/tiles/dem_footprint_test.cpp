// The DEM's footprint on the map and the tiles it touches.
#include "core/tiles/dem_footprint.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/geo/crs.hpp"
#include "core/tiles/tile_export.hpp"
#include "core/tiles/zoom_exaggeration.hpp"

namespace ts::tiles {
namespace {

geo::Georef anatolia() {
    // srtm3_N39E040_1000px.tif: origin 40E 40N, 1/1200 degree pixels.
    geo::GeoTransform t;
    t.x0 = 40.0, t.dx_col = 1.0 / 1200, t.y0 = 40.0, t.dy_row = -1.0 / 1200;
    return geo::Georef(1000, 1000, t, geo::Crs::wgs84(), true);
}

TEST(DemFootprint, GeographicDemIsItsCornerBox) {
    const LonLatBox b = dem_footprint(anatolia());
    EXPECT_NEAR(b.west, 40.0, 1e-12);
    EXPECT_NEAR(b.east, 40.0 + 1000.0 / 1200, 1e-12);
    EXPECT_NEAR(b.north, 40.0, 1e-12);
    EXPECT_NEAR(b.south, 40.0 - 1000.0 / 1200, 1e-12);
}

// A nodata collar is not the map: the MBTiles bounds (and the tiles planned) are the terrain's.
TEST(DemFootprint, TheTerrainsFootprintLeavesTheCollarOut) {
    dem::Dem d;
    d.width = d.height = 1000;
    d.georef = anatolia();
    d.z.assign(std::size_t(1000) * 1000, 500.0f);
    d.void_mask.assign(d.z.size(), 0);
    const LonLatBox whole = terrain_footprint(d);  // no collar: the DEM's outline, exactly
    const LonLatBox outline = dem_footprint(d.georef);
    EXPECT_EQ(whole.west, outline.west);
    EXPECT_EQ(whole.east, outline.east);
    EXPECT_EQ(whole.south, outline.south);
    EXPECT_EQ(whole.north, outline.north);
    // Columns 0..199 and rows 700..999 are a collar (NaN: fill_voids leaves it outside).
    for (int r = 0; r < 1000; ++r)
        for (int c = 0; c < 1000; ++c)
            if (c < 200 || r >= 700) d.z[d.index(c, r)] = NAN, d.void_mask[d.index(c, r)] = 1;
    const LonLatBox b = terrain_footprint(d);
    EXPECT_NEAR(b.west, 40.0 + 200.0 / 1200, 1e-9);
    EXPECT_NEAR(b.east, 40.0 + 1000.0 / 1200, 1e-9);
    EXPECT_NEAR(b.north, 40.0, 1e-9);
    EXPECT_NEAR(b.south, 40.0 - 700.0 / 1200, 1e-9);
    EXPECT_LT(tiles_covering(b, 14, 14).size(), tiles_covering(outline, 14, 14).size());
}

// A DEM around a pole (polar stereographic, 6000 km square on the North Pole) reaches Web
// Mercator's edge all the way round: its outline never does, the pole inside it does.
TEST(DemFootprint, ADemAroundAPoleReachesTheMapsEdge) {
    for (const int epsg : {3413, 3031}) {
        const auto crs = geo::Crs::from_epsg(epsg);
        geo::GeoTransform t{-3e6, 50000, 0, 3e6, 0, -50000};
        dem::Dem d;
        d.width = d.height = 120;
        d.georef = geo::Georef(120, 120, t, crs, true);
        d.z.assign(std::size_t(120) * 120, 100.0f);
        d.void_mask.assign(d.z.size(), 0);
        for (const LonLatBox& b : {dem_footprint(d.georef), terrain_footprint(d)}) {
            EXPECT_EQ(b.west, -180.0) << epsg;
            EXPECT_EQ(b.east, 180.0) << epsg;
            if (epsg == 3413) EXPECT_EQ(b.north, kMaxLatitudeDeg);
            else EXPECT_EQ(b.south, -kMaxLatitudeDeg);
            // Zoom 2's polar row is planned: 4 tiles across.
            int polar = 0;
            for (const TileId& id : tiles_covering(b, 2, 2)) polar += epsg == 3413 ? id.y == 0 : id.y == 3;
            EXPECT_EQ(polar, 4) << epsg;
        }
        // Without terrain at the pole (its texels void), the terrain's box stops at its outline.
        for (int r = 50; r < 70; ++r)
            for (int c = 50; c < 70; ++c) d.z[d.index(c, r)] = NAN;
        EXPECT_LT(std::abs(epsg == 3413 ? terrain_footprint(d).north : terrain_footprint(d).south), kMaxLatitudeDeg);
    }
}

TEST(DemFootprint, TilesCoveringAreTheIntersectingOnes) {
    const LonLatBox b = dem_footprint(anatolia());
    const auto tiles = tiles_covering(b, 0, 12);
    ASSERT_FALSE(tiles.empty());
    int per_zoom[13] = {};
    for (const TileId& t : tiles) {
        ++per_zoom[t.z];
        // Every listed tile overlaps the box (not only touches it).
        const MercatorBounds m = tile_bounds(t);
        const glm::dvec2 sw = lonlat_to_mercator({b.west, b.south}), ne = lonlat_to_mercator({b.east, b.north});
        EXPECT_LT(m.x0, ne.x);
        EXPECT_GT(m.x1, sw.x);
        EXPECT_LT(m.y0, ne.y);
        EXPECT_GT(m.y1, sw.y);
    }
    EXPECT_EQ(per_zoom[0], 1);
    // z12: 0.833 deg of longitude = 9.5 tile widths, of latitude (sec 39.6) ~ 12.3 tile heights.
    EXPECT_GE(per_zoom[12], 10 * 13);
    EXPECT_LE(per_zoom[12], 11 * 14);
}

TEST(DemFootprint, BeyondMercatorIsEmpty) {
    geo::GeoTransform t;
    t.x0 = 0, t.dx_col = 0.01, t.y0 = 89.9, t.dy_row = -0.01;
    const auto box = dem_footprint(geo::Georef(100, 4, t, geo::Crs::wgs84(), true));
    EXPECT_TRUE(box.empty());
    EXPECT_TRUE(tiles_covering(box, 0, 5).empty());
}

TEST(ZoomExaggeration, FormulaAndLevels) {
    EXPECT_DOUBLE_EQ(zoom_exaggeration(12), 1.0);
    EXPECT_DOUBLE_EQ(zoom_exaggeration(15), 1.0);
    EXPECT_DOUBLE_EQ(zoom_exaggeration(9), 2.0);
    EXPECT_DOUBLE_EQ(zoom_exaggeration(0), 16.0);
    EXPECT_EQ(pyramid_level_for(80.0, 30.0, 5), 0);
    EXPECT_EQ(pyramid_level_for(80.0, 159.0, 5), 0);
    EXPECT_EQ(pyramid_level_for(80.0, 161.0, 5), 1);
    EXPECT_EQ(pyramid_level_for(80.0, 1e6, 5), 5);
}

// Zooms finer than the DEM's native one are magnifications of it: they shade from level 0 with
// the native zoom's exaggeration, so they share one source; coarser zooms keep E(P).
TEST(ZoomExaggeration, OverZoomedZoomsKeepTheNativeZoomsExaggeration) {
    dem::Dem dem;
    dem.width = dem.height = 1000;
    dem.georef = anatolia();
    dem.z.assign(std::size_t(1000) * 1000, 100.0f);
    TileJob job;
    // The 90 m DEM at 39.6 N: pixel zoom 10 (118 m pixels) is the coarsest shaded from level 0.
    const ZoomShading z9 = zoom_shading(dem, job, 9), z10 = zoom_shading(dem, job, 10);
    EXPECT_EQ(z9.level, 1);
    EXPECT_DOUBLE_EQ(z9.vertical_scale, zoom_exaggeration(9));
    EXPECT_EQ(z10.level, 0);
    EXPECT_DOUBLE_EQ(z10.vertical_scale, zoom_exaggeration(10));
    for (int pz : {11, 12, 13, 16}) {
        const ZoomShading z = zoom_shading(dem, job, pz);
        EXPECT_EQ(z.level, 0) << pz;
        EXPECT_DOUBLE_EQ(z.vertical_scale, z10.vertical_scale) << pz;
    }
    job.shading.z_factor = 2;
    EXPECT_DOUBLE_EQ(zoom_shading(dem, job, 12).vertical_scale, 2 * zoom_exaggeration(10));
    job.shading.exaggeration = 1.0;  // a constant replaces the rule at every zoom
    EXPECT_DOUBLE_EQ(zoom_shading(dem, job, 12).vertical_scale, 2.0);
    EXPECT_DOUBLE_EQ(zoom_shading(dem, job, 8).vertical_scale, 2.0);
    // --level-bias moves the level, clamped to the DEM's levels, and leaves the exaggeration.
    job.shading.exaggeration.reset();
    job.level_bias = 1;
    EXPECT_EQ(zoom_shading(dem, job, 9).level, 2);
    EXPECT_EQ(zoom_shading(dem, job, 12).level, 1);
    EXPECT_DOUBLE_EQ(zoom_shading(dem, job, 12).vertical_scale, 2 * zoom_exaggeration(10));
    job.level_bias = -1;
    EXPECT_EQ(zoom_shading(dem, job, 9).level, 0);
    EXPECT_EQ(zoom_shading(dem, job, 12).level, 0);
    job.level_bias = 4;
    const int coarsest = zoom_shading(dem, job, 0).level;
    job.level_bias = 0;
    EXPECT_EQ(zoom_shading(dem, job, 0).level, coarsest);  // z0 is already at the coarsest level
}

}  // namespace
}  // namespace ts::tiles
