// The sun's azimuth is from true north; a projected grid's north is not (the meridian
// convergence: 50 degrees at 5.5 E on the polar stereographic EPSG:3413, whose grid north is
// 45 W). A cone lit from the true east must be brightest on its true east flank, wherever the
// grid puts it.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/geo/crs.hpp"
#include "core/render/render_scene.hpp"

namespace ts::render {
namespace {

constexpr int kSize = 81;
constexpr double kCell = 100.0;  // metres

// A cone 1500 m high and 3.5 km across, its centre at `centre` (lon/lat) on a grid in `epsg`.
dem::Dem cone(int epsg, glm::dvec2 centre) {
    dem::Dem d;
    d.width = d.height = kSize;
    const auto crs = geo::Crs::from_epsg(epsg);
    const glm::dvec2 c = crs->from_lonlat(centre);
    const double half = kSize * kCell / 2;
    d.georef = geo::Georef(kSize, kSize, {c.x - half, kCell, 0.0, c.y + half, 0.0, -kCell}, crs, true);
    d.z.resize(std::size_t(kSize) * kSize);
    for (int r = 0; r < kSize; ++r)
        for (int col = 0; col < kSize; ++col) {
            const double dist = std::hypot(col - kSize / 2.0 + 0.5, r - kSize / 2.0 + 0.5) * kCell;
            d.z[std::size_t(r) * kSize + col] = float(500.0 + std::max(0.0, 1500.0 - dist * 0.85));
        }
    d.void_mask.assign(d.z.size(), 0);
    return d;
}

// The grid azimuth (clockwise from the grid's up) of the cone's bright flank: the mean direction
// of its slopes weighted by how much brighter than average each texel is.
double bright_flank_grid_azimuth(const LinearImage& image) {
    double mean = 0;
    for (const glm::vec3& c : image.rgb) mean += c.y;
    mean /= double(image.rgb.size());
    double se = 0, sn = 0;
    for (int r = 0; r < image.height; ++r)
        for (int col = 0; col < image.width; ++col) {
            const double east = col - kSize / 2.0 + 0.5, north = kSize / 2.0 - 0.5 - r;
            const double dist = std::hypot(east, north);
            if (dist < 4 || dist > 15) continue;  // on the flanks, not the summit or the plain
            const double w = std::max(0.0, double(image.rgb[std::size_t(r) * image.width + col].y) - mean);
            se += w * east / dist, sn += w * north / dist;
        }
    return std::atan2(se, sn) * 180.0 / std::numbers::pi;
}

TEST(GridNorth, TheSunsTrueAzimuthIsTurnedOntoAProjectedGrid) {
    const dem::Dem polar = cone(3413, {5.5, 45.2});
    const double north = polar.georef.grid_azimuth_of_north_deg();
    ASSERT_NEAR(north, -50.5, 0.01);  // -(5.5 - -45): meridians meet at the pole
    SceneOptions options;
    options.renderer.directions = 16;
    Scene scene(polar, options);
    LinearImage image;
    const SunState east{90.0, 30.0};
    scene.render(scene.on_grid(east), image);
    EXPECT_NEAR(bright_flank_grid_azimuth(image), 90.0 + north, 3.0);

    // A geographic grid's north is true north: nothing turns.
    const dem::Dem geographic = [] {
        dem::Dem d = cone(32631, {3.0, 45.2});  // heights only
        const glm::dvec2 ll = d.georef.pixel_to_lonlat(0, 0);
        const double dlat = kCell / 111132.0, dlon = dlat / std::cos(45.2 * std::numbers::pi / 180);
        d.georef = geo::Georef(kSize, kSize, {ll.x, dlon, 0.0, ll.y, 0.0, -dlat}, geo::Crs::wgs84(), true);
        return d;
    }();
    Scene flat_north(geographic, options);
    EXPECT_EQ(flat_north.grid_north_deg(), 0.0);
    flat_north.render(flat_north.on_grid(east), image);
    EXPECT_NEAR(bright_flank_grid_azimuth(image), 90.0, 3.0);
}

}  // namespace
}  // namespace ts::render
