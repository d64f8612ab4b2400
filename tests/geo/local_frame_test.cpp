#include "core/geo/local_frame.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/geo/georef.hpp"

using namespace ts::geo;

TEST(LocalFrame, OriginIsZeroAndRoundTrips) {
    const LocalFrame f({5.72, 45.19, 212.0});
    const glm::dvec3 o = f.to_enu({5.72, 45.19, 212.0});
    EXPECT_NEAR(glm::length(o), 0.0, 1e-9);
    const glm::dvec3 p{1234.5, -987.25, 345.0};
    const glm::dvec3 back = f.to_enu(f.to_lonlat_h(p));
    // LocalCartesian round trips to ~1e-9 m; 1e-6 m flags any lossy conversion.
    EXPECT_NEAR(back.x, p.x, 1e-6);
    EXPECT_NEAR(back.y, p.y, 1e-6);
    EXPECT_NEAR(back.z, p.z, 1e-6);
}

TEST(LocalFrame, AxesAreEastNorthUpAndTheEarthCurvesAway) {
    const LocalFrame f({10.0, 0.0, 0.0});
    const glm::dvec3 east = f.to_enu({10.01, 0.0, 0.0});   // ~1113 m east along the equator
    const glm::dvec3 north = f.to_enu({10.0, 0.01, 0.0});  // ~1106 m north
    EXPECT_GT(east.x, 1100);
    EXPECT_NEAR(east.y, 0.0, 1e-6);
    EXPECT_GT(north.y, 1100);
    EXPECT_NEAR(north.x, 0.0, 1e-6);
    // Drop of the ellipsoid below the tangent plane: d^2 / (2R), R = a at the equator going east.
    EXPECT_NEAR(east.z, -east.x * east.x / (2 * 6378137.0), 1e-3);  // 1 mm: higher-order terms are ~1e-7 m
}

TEST(LocalFrame, PixelToEnuUsesTheGeoref) {
    GeoTransform t{10.0, 0.001, 0, 1.0, 0, -0.001};
    const Georef g(100, 100, t, Crs::wgs84(), true);
    const LocalFrame f = LocalFrame::at_raster_centre(g);
    const glm::dvec3 c = f.pixel_to_enu(g, 50, 50, 0.0);
    EXPECT_NEAR(glm::length(c), 0.0, 1e-6);
    const glm::dvec3 right = f.pixel_to_enu(g, 51, 50, 0.0);
    EXPECT_NEAR(right.x, g.cell_size_m(50.5, 50).x, 1e-3);
}
