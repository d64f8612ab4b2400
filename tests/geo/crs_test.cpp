#include "core/geo/crs.hpp"
#include "core/util/angles.hpp"

#include <cmath>
#include <thread>
#include <vector>

#include <GeographicLib/UTMUPS.hpp>
#include <gtest/gtest.h>

#include "core/util/error.hpp"

using ts::geo::Crs;
using ts::kPi;
using ts::radians;

namespace {
// PROJ and GeographicLib both implement the Krueger series for transverse Mercator to well
// under a millimetre; 1 mm leaves room for nothing but genuine disagreement.
constexpr double kProjectionAgreementM = 1e-3;
// Round trips through PROJ: transverse Mercator is exact to ~1e-9 m, but PROJ 9.1's LAEA
// inverts the authalic latitude by a series good to ~0.5 mm; 1 mm (1e-8 deg) still flags
// any real loss (a wrong datum step is metres).
constexpr double kRoundTripM = 1e-3;
constexpr double kRoundTripDeg = 1e-8;
}  // namespace

TEST(Crs, Wgs84IsGeographicWithCode4326) {
    auto crs = Crs::wgs84();
    EXPECT_EQ(crs->epsg(), 4326);
    EXPECT_TRUE(crs->is_geographic());
    EXPECT_EQ(crs->name(), "WGS 84");
    const glm::dvec2 p = crs->to_lonlat({12.5, -7.25});
    EXPECT_EQ(p.x, 12.5);  // lon first, untouched
    EXPECT_EQ(p.y, -7.25);
}

TEST(Crs, UtmNorthAndSouthAgreeWithGeographicLib) {
    for (const auto& [code, lon, lat] : {std::tuple{32633, 16.3, 47.1}, std::tuple{32733, 11.2, -0.4},
                                         std::tuple{32637, 40.4, 39.6}, std::tuple{32718, -77.0, -12.0}}) {
        auto crs = Crs::from_epsg(code);
        EXPECT_FALSE(crs->is_geographic());
        EXPECT_EQ(crs->epsg(), code);
        int zone = 0;
        bool north = false;
        double x = 0, y = 0;
        GeographicLib::UTMUPS::Forward(lat, lon, zone, north, x, y, /*setzone=*/code % 100);
        const glm::dvec2 xy = crs->from_lonlat({lon, lat});
        EXPECT_NEAR(xy.x, x, kProjectionAgreementM) << code;
        EXPECT_NEAR(xy.y, y, kProjectionAgreementM) << code;
        const glm::dvec2 back = crs->to_lonlat(xy);
        EXPECT_NEAR(back.x, lon, kRoundTripDeg);
        EXPECT_NEAR(back.y, lat, kRoundTripDeg);
    }
}

TEST(Crs, UpsNorthIsNormalisedToEastingNorthing) {
    // EPSG:32661 declares its axes northing-first; the normalised transform must still give (E, N).
    auto crs = Crs::from_epsg(32661);
    int zone = 0;
    bool north = false;
    double x = 0, y = 0;
    GeographicLib::UTMUPS::Forward(85.0, 30.0, zone, north, x, y);
    const glm::dvec2 xy = crs->from_lonlat({30.0, 85.0});
    EXPECT_NEAR(xy.x, x, kProjectionAgreementM);
    EXPECT_NEAR(xy.y, y, kProjectionAgreementM);
}

TEST(Crs, WebMercatorMatchesItsClosedForm) {
    auto crs = Crs::from_epsg(3857);
    const double r = 6378137.0, lon = 5.7, lat = 45.2;
    const glm::dvec2 xy = crs->from_lonlat({lon, lat});
    EXPECT_NEAR(xy.x, r * radians(lon), kProjectionAgreementM);
    EXPECT_NEAR(xy.y, r * std::log(std::tan(kPi / 4 + radians(lat) / 2)), kProjectionAgreementM);
}

TEST(Crs, ProjectedCrssRoundTrip) {
    for (int code : {3413, 3031, 3035, 2154, 5070, 25831, 3577}) {
        auto crs = Crs::from_epsg(code);
        EXPECT_FALSE(crs->name().empty());
        // A point inside each CRS's area of use.
        glm::dvec2 ll{5.5, 45.5};
        if (code == 3413) ll = {-45.0, 75.0};
        if (code == 3031) ll = {60.0, -75.0};
        if (code == 5070) ll = {-100.0, 40.0};
        if (code == 3577) ll = {134.0, -25.0};
        const glm::dvec2 xy = crs->from_lonlat(ll);
        const glm::dvec2 back = crs->to_lonlat(xy);
        EXPECT_NEAR(back.x, ll.x, kRoundTripDeg) << code;
        EXPECT_NEAR(back.y, ll.y, kRoundTripDeg) << code;
        const glm::dvec2 again = crs->from_lonlat(back);
        EXPECT_NEAR(again.x, xy.x, kRoundTripM) << code;
    }
}

TEST(Crs, ProjStringIsIdentifiedAsItsEpsgCode) {
    auto crs = Crs::from_definition("+proj=utm +zone=33 +datum=WGS84 +units=m +no_defs +type=crs");
    EXPECT_EQ(crs->epsg(), 32633);
    EXPECT_TRUE(crs->same_as(*Crs::from_epsg(32633)));
    EXPECT_FALSE(crs->same_as(*Crs::from_epsg(32632)));
}

TEST(Crs, UnknownDefinitionsThrowInputError) {
    EXPECT_THROW(Crs::from_definition("EPSG:999999"), ts::InputError);
    EXPECT_THROW(Crs::from_definition("not a crs"), ts::InputError);
    EXPECT_THROW(Crs::from_definition("+proj=tmerc +lon_0=3"), ts::InputError);  // a conversion, not a CRS
}

TEST(Crs, ToLonLatIsThreadSafe) {
    auto crs = Crs::from_epsg(32633);
    std::vector<glm::dvec2> expected;
    for (int i = 0; i < 500; ++i) expected.push_back(crs->to_lonlat({400000.0 + i * 100.0, 5000000.0 + i * 37.0}));
    std::vector<int> mismatches(4, 0);
    {
        std::vector<std::jthread> threads;
        for (int t = 0; t < 4; ++t)
            threads.emplace_back([&, t] {
                for (int rep = 0; rep < 20; ++rep)
                    for (int i = 0; i < 500; ++i)
                        if (crs->to_lonlat({400000.0 + i * 100.0, 5000000.0 + i * 37.0}) != expected[std::size_t(i)])
                            ++mismatches[std::size_t(t)];
            });
    }
    for (int m : mismatches) EXPECT_EQ(m, 0);
}
