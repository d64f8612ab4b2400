// A global grid in degrees widened across 180 (core/dem/wrap_longitude.hpp): each added column
// is the column 360 degrees away; other grids are left as they are.
#include "core/dem/wrap_longitude.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/geo/crs.hpp"

namespace ts::dem {
namespace {

Dem global_one_degree() {  // ETOPO1's layout: 361 columns, edges -180.5..180.5
    Dem d;
    d.width = 361, d.height = 3;
    d.georef = geo::Georef(361, 3, {-180.5, 1.0, 0.0, 1.5, 0.0, -1.0}, geo::Crs::wgs84(), true);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 361; ++c) d.z.push_back(float(c == 360 ? 0 : c) + 1000.0f * float(r));  // 180 E is 180 W
    d.void_mask.assign(d.z.size(), 0);
    d.void_mask[5] = 1;
    return d;
}

TEST(WrapLongitude, AddedColumnsAreTheColumnsATurnAway) {
    const Dem d = global_one_degree();
    ASSERT_TRUE(spans_all_longitudes(d));
    const Dem w = wrap_longitudes(d, 45);
    EXPECT_EQ(w.width, 361 + 90);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < w.width; ++c) {
            const double lon = w.georef.pixel_to_lonlat(c + 0.5, r + 0.5).x;
            const double turned = std::fmod(lon + 180.0 + 3600.0, 360.0) - 180.0;  // into -180..180
            const int src = int(std::lround(turned + 180.0));
            EXPECT_EQ(w.z[w.index(c, r)], d.z[d.index(src == 360 ? 0 : src, r)]) << c << " " << r << " at " << lon;
        }
    EXPECT_EQ(w.void_mask[w.index(45 + 5, 0)], 1);
    EXPECT_EQ(w.void_mask[w.index(45 + 5 + 360, 0)], 1);  // its copy a turn east
}

TEST(WrapLongitude, OtherGridsAreLeftAsTheyAre) {
    Dem d = global_one_degree();
    d.width = 200, d.z.resize(600), d.void_mask.resize(600);
    d.georef = geo::Georef(200, 3, {-10.0, 1.0, 0.0, 1.5, 0.0, -1.0}, geo::Crs::wgs84(), true);
    EXPECT_FALSE(spans_all_longitudes(d));
    EXPECT_EQ(wrap_longitudes(d, 45).width, 200);
    const auto utm = geo::Crs::from_epsg(32631);
    d.georef = geo::Georef(200, 3, {500000.0, 30.0, 0.0, 5e6, 0.0, -30.0}, utm, true);
    EXPECT_FALSE(spans_all_longitudes(d));
}

}  // namespace
}  // namespace ts::dem
