// metric_view: per-row spacing from the georeferencing, so geographic grids get true metres.
#include "core/terrain/dem_height_grid.hpp"
#include "core/util/angles.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/util/error.hpp"

namespace ts::terrain {
namespace {

dem::Dem make_dem(int w, int h, geo::GeoTransform t, int epsg) {
    dem::Dem d;
    d.width = w;
    d.height = h;
    d.z.assign(std::size_t(w) * std::size_t(h), 100.0f);
    d.void_mask.assign(d.z.size(), 0);
    d.georef = geo::Georef(w, h, t, geo::Crs::from_epsg(epsg), true);
    d.source = "synthetic";
    return d;
}

TEST(MetricView, GeographicEastWestSpacingShrinksWithLatitude) {
    // 3 arc-second cells from 60N down to 59N: 1200 rows.
    const double step = 1.0 / 1200.0;
    const dem::Dem d = make_dem(10, 1200, {10.0, step, 0.0, 60.0, 0.0, -step}, 4326);
    const HeightGrid g = metric_view(d);
    ASSERT_EQ(g.dx_m.size(), 1200u);
    // WGS84 parallel arc: N(lat) cos(lat) dlon, with N the prime vertical radius. Checked to 1e-6
    // relative (the geodesic between two points of a parallel is shorter by far less than that).
    const double a = 6378137.0, f = 1 / 298.257223563, e2 = f * (2 - f);
    for (int r : {0, 599, 1199}) {
        const double lat = radians(60.0 - (r + 0.5) * step);
        const double n = a / std::sqrt(1 - e2 * std::sin(lat) * std::sin(lat));
        const double want_dx = n * std::cos(lat) * radians(step);
        EXPECT_NEAR(g.dx_m[std::size_t(r)], want_dx, want_dx * 1e-6) << r;
        // Meridian arc: M(lat) dlat, M = a (1 - e2) / (1 - e2 sin^2)^1.5.
        const double m = a * (1 - e2) / std::pow(1 - e2 * std::sin(lat) * std::sin(lat), 1.5);
        EXPECT_NEAR(g.dy_m[std::size_t(r)], m * radians(step), 1e-4) << r;
    }
    EXPECT_GT(g.dx_m[1199], g.dx_m[0]);  // further south = wider
    EXPECT_EQ(g.z.data(), d.z.data());     // a view, not a copy
}

TEST(MetricView, ProjectedSpacingIsMapUnitsOverTheScaleFactor) {
    // UTM 32N, 30 m cells on the central meridian (9E), where the scale factor is 0.9996.
    const dem::Dem d = make_dem(20, 20, {500000.0 - 300, 30.0, 0.0, 5000000.0, 0.0, -30.0}, 32632);
    const HeightGrid g = metric_view(d);
    EXPECT_NEAR(g.dx_m[10], 30.0 / 0.9996, 2e-3);
    EXPECT_NEAR(g.dy_m[10], 30.0 / 0.9996, 2e-3);
}

TEST(MetricView, RequiresGeoreferencing) {
    dem::Dem d;
    d.width = d.height = 2;
    d.z.assign(4, 0.0f);
    d.source = "nogeo.tif";
    EXPECT_THROW(metric_view(d), InputError);
}

}  // namespace
}  // namespace ts::terrain
