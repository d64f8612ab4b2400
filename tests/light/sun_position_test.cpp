// The SPA against the example published in Reda & Andreas (NREL/TP-560-34302, table A5.1 and
// the spa_tester output), then physical sanity cases that do not depend on the paper.
#include "core/light/sun_position.hpp"
#include "core/util/angles.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/light/utc_time.hpp"
#include "core/util/error.hpp"

namespace ts::light {
namespace {

using std::chrono::minutes;
using std::chrono::seconds;

// The published example: 2003-10-17 12:30:30 at UTC-7, Golden (Colorado), 1830.14 m,
// 820 mbar, 11 C, delta T 67 s.
SunPositionInput published_example() {
    SunPositionInput in;
    in.time = parse_utc_time("2003-10-17T12:30:30-07:00");
    in.observer = {39.742476, -105.1786, 1830.14};
    in.atmosphere = {820.0, 11.0};
    in.delta_t_s = 67.0;
    return in;
}

TEST(SunPosition, PublishedExampleResults) {
    const SunPosition s = sun_position(published_example());
    // The paper prints 5 decimals (50.11162, 194.34024); its uncertainty claim is 0.0003 deg.
    // 0.001 deg leaves room for the last printed digit only, so a wrong table entry fails here.
    EXPECT_NEAR(s.zenith_deg, 50.11162, 0.001);
    EXPECT_NEAR(s.azimuth_deg, 194.34024, 0.001);
    EXPECT_NEAR(s.elevation_deg, 90.0 - 50.11162, 0.001);
    EXPECT_NEAR(s.zenith_deg + s.elevation_deg, 90.0, 1e-12);
    // Surface slope 30 deg, azimuth rotation -10 (10 deg east of south = 170 clockwise from north).
    EXPECT_NEAR(incidence_angle_deg(s, 30.0, 170.0), 25.18700, 0.001);
}

TEST(SunPosition, PublishedExampleIntermediates) {
    const SunPosition s = sun_position(published_example());
    // Each to about the last digit the paper prints (L, B, R to 1e-9..1e-10: a periodic term
    // wrong by one unit of 1e-8 rad, 6e-7 deg, would show), so a wrong table entry shows up in
    // the quantity it belongs to, even where the final angles would hide it.
    EXPECT_NEAR(s.julian_day, 2452930.312847, 1e-6);
    EXPECT_NEAR(s.heliocentric_longitude_deg, 24.0182616917, 1e-9);
    EXPECT_NEAR(s.heliocentric_latitude_deg, -0.0001011219, 1e-10);
    EXPECT_NEAR(s.earth_sun_distance_au, 0.9965422974, 1e-10);
    EXPECT_NEAR(s.observer_hour_angle_deg, 11.105900, 1e-5);
    EXPECT_NEAR(s.nutation_longitude_deg, -0.00399840, 1e-8);
    EXPECT_NEAR(s.nutation_obliquity_deg, 0.00166657, 1e-8);
    EXPECT_NEAR(s.true_obliquity_deg, 23.440465, 1e-6);
    EXPECT_NEAR(s.apparent_sun_longitude_deg, 204.0085519281, 1e-6);
    EXPECT_NEAR(s.apparent_sidereal_time_deg, 318.5119, 1e-4);
    EXPECT_NEAR(s.right_ascension_deg, 202.22741, 1e-5);
    EXPECT_NEAR(s.declination_deg, -9.31434, 1e-5);
    EXPECT_NEAR(s.topocentric_declination_deg, -9.316179, 1e-6);
    // H' = H - delta alpha, with the paper's parallax in right ascension delta alpha = -0.000369 deg.
    EXPECT_NEAR(s.topocentric_hour_angle_deg, 11.105900 + 0.000369, 5e-6);
    EXPECT_NEAR(s.elevation_unrefracted_deg, 39.872046, 1e-6);
}

TEST(SunPosition, DirectionMatchesAzimuthAndElevation) {
    const SunPosition s = sun_position(published_example());
    const glm::dvec3 d = sun_direction_enu(s);
    EXPECT_NEAR(d.x * d.x + d.y * d.y + d.z * d.z, 1.0, 1e-12);
    EXPECT_NEAR(degrees(std::asin(d.z)), s.elevation_deg, 1e-9);
    // Azimuth 194 deg: a little west of south, so east < 0 and north < 0.
    EXPECT_LT(d.x, 0.0);
    EXPECT_LT(d.y, 0.0);
    EXPECT_NEAR(degrees(std::atan2(d.x, d.y)) + 360.0, s.azimuth_deg, 1e-9);
}

// At the March equinox 2024 (2024-03-20 03:06 UTC, IMCCE/USNO) the declination is 0, so along
// the equator the smallest zenith angle is about 0 and lies where it is apparent noon.
TEST(SunPosition, EquinoxNoonAtTheEquatorIsNearZenith) {
    SunPositionInput in;
    in.time = parse_utc_time("2024-03-20T03:06:00Z");
    // The declination changes 0.0003 deg per minute near the equinox; the published instant is
    // rounded to the minute.
    const double dec = sun_position(in).declination_deg;
    EXPECT_NEAR(dec, 0.0, 0.001);
    // Golden-section search of the zenith along the equator.
    double lo = 100.0, hi = 170.0;
    const auto zenith_at = [&](double lon) {
        in.observer = {0.0, lon, 0.0};
        return sun_position(in).zenith_deg;
    };
    for (int i = 0; i < 80; ++i) {
        const double a = lo + (hi - lo) * 0.382, b = lo + (hi - lo) * 0.618;
        if (zenith_at(a) < zenith_at(b))
            hi = b;
        else
            lo = a;
    }
    const double lon = 0.5 * (lo + hi);
    // Minimum zenith = |declination| + parallax (0.0024 deg) - refraction (0 at the zenith).
    EXPECT_LT(zenith_at(lon), 0.005);
    // Apparent noon at 03:06 UTC with the equation of time of 20 March (-7.5 +- 0.5 min):
    // longitude 15 * (12 - 3.1 + 7.5/60) = 135.4 deg; 0.5 min of time is 0.125 deg.
    EXPECT_NEAR(lon, 135.4, 0.15);
}

// Noon azimuth: due south in the northern mid-latitudes, due north in the southern ones.
TEST(SunPosition, NoonAzimuthPointsToTheEquator) {
    for (const double lat : {45.0, -45.0}) {
        SunPositionInput in;
        in.observer = {lat, 0.0, 0.0};
        const UtcTime day = parse_utc_time("2024-06-21T10:00:00Z");
        double best_elevation = -90.0, azimuth_at_best = 0.0;
        for (int m = 0; m <= 240; ++m) {  // 10:00..14:00 UTC by the minute
            in.time = day + minutes(m);
            const SunPosition s = sun_position(in);
            if (s.elevation_deg > best_elevation) best_elevation = s.elevation_deg, azimuth_at_best = s.azimuth_deg;
        }
        // One minute from culmination the sun moves at most 0.5 deg in azimuth (at 45 deg it is
        // about 0.3 deg/min near noon in June).
        if (lat > 0)
            EXPECT_NEAR(azimuth_at_best, 180.0, 0.5);
        else
            EXPECT_NEAR(std::remainder(azimuth_at_best, 360.0), 0.0, 0.5);
        // Culmination: 90 - |lat - dec| with dec = +23.44 deg at the June solstice, plus refraction.
        const double expected = 90.0 - std::abs(lat - 23.44);
        EXPECT_NEAR(best_elevation, expected, lat > 0 ? 0.05 : 0.1);  // refraction 0.02 deg at 68, 0.08 at 21.5
    }
}

// Polar night: at 80 N on the December solstice the sun never rises; it culminates at
// 90 - (80 + 23.437) = -13.437 deg (declination -23.4367 deg, 2024-12-21 09:20 UTC), where no
// refraction applies.
TEST(SunPosition, PolarNightNeverRises) {
    SunPositionInput in;
    in.observer = {80.0, 0.0, 0.0};
    const UtcTime day = parse_utc_time("2024-12-21T00:00:00Z");
    double highest = -90.0;
    for (int m = 0; m < 24 * 60; ++m) {
        in.time = day + minutes(m);
        const SunPosition s = sun_position(in);
        highest = std::max(highest, s.elevation_deg);
        EXPECT_EQ(s.elevation_deg, s.elevation_unrefracted_deg);  // below the refraction threshold
    }
    // The declination changes < 0.001 deg in the day around the solstice; parallax adds 0.0024 deg.
    EXPECT_NEAR(highest, -13.437, 0.01);
}

// Polar day: at the South Pole on the same day the sun circles at about +23.44 deg.
TEST(SunPosition, SouthPoleMidsummerCircles) {
    SunPositionInput in;
    in.observer = {-90.0, 0.0, 2835.0};
    in.atmosphere = Atmosphere::standard_at(2835.0);
    const UtcTime day = parse_utc_time("2024-12-21T00:00:00Z");
    for (int h = 0; h < 24; ++h) {
        in.time = day + std::chrono::hours(h);
        // Elevation = -declination + refraction (0.03 deg at 23 deg and 720 hPa).
        EXPECT_NEAR(sun_position(in).elevation_deg, 23.437 + 0.03, 0.02) << h;
    }
}

// Sunrise: the paper's spa_tester prints sunrise 06:12:43 local (13:12:43 UTC) for its example
// day and place, defined as the moment the sun's centre is at -(0.26667 + 0.5667) deg
// unrefracted. Find that crossing by bisection on our elevation and compare.
TEST(SunPosition, SunriseCrossingMatchesThePublishedSunrise) {
    SunPositionInput in = published_example();
    const double h0 = -(kSunRadiusDeg + kHorizonRefractionDeg);
    UtcTime lo = parse_utc_time("2003-10-17T12:00:00Z"), hi = parse_utc_time("2003-10-17T14:30:00Z");
    const auto elevation0 = [&](UtcTime t) {
        in.time = t;
        return sun_position(in).elevation_unrefracted_deg;
    };
    ASSERT_LT(elevation0(lo), h0);
    ASSERT_GT(elevation0(hi), h0);
    while (hi - lo > std::chrono::milliseconds(100)) {
        const UtcTime mid = lo + (hi - lo) / 2;
        (elevation0(mid) < h0 ? lo : hi) = mid;
    }
    const double offset_s = std::chrono::duration<double>(lo - parse_utc_time("2003-10-17T13:12:43Z")).count();
    // The published time is rounded to the second and comes from the SPA's rise/set interpolation
    // of geocentric positions; parallax shifts the topocentric crossing by about 1 s. 10 s is
    // 0.03 deg of elevation at this rate of rise.
    EXPECT_NEAR(offset_s, 0.0, 10.0);
    // At that moment the refraction just applies and lifts the sun by about half a degree.
    in.time = hi;
    const SunPosition s = sun_position(in);
    EXPECT_GT(s.elevation_deg - s.elevation_unrefracted_deg, 0.4);
}

TEST(SunPosition, RefractionFollowsTheSpaFormula) {
    const Atmosphere standard{1010.0, 10.0};
    // 1.02 / tan(10.3 / 5.11 deg) arcmin at the horizon, 28.98'.
    EXPECT_NEAR(refraction_correction_deg(0.0, standard), 28.98 / 60.0, 0.01 / 60.0);
    // Below the SPA's threshold (the whole disc below a sea-level horizon) it fades, without a
    // jump, to nothing at kRefractionEndDeg; the refracted sun still sinks as the true one does.
    const double threshold = -(kSunRadiusDeg + kHorizonRefractionDeg);
    EXPECT_NEAR(refraction_correction_deg(threshold - 1e-6, standard), refraction_correction_deg(threshold, standard),
                1e-5);
    EXPECT_GT(refraction_correction_deg(threshold + 1e-6, standard), 0.5);
    EXPECT_EQ(refraction_correction_deg(kRefractionEndDeg, standard), 0.0);
    EXPECT_EQ(refraction_correction_deg(-10.0, standard), 0.0);
    double last = 2.0 + refraction_correction_deg(2.0, standard);
    for (double e = 1.99; e >= -6.0; e -= 0.01) {
        const double apparent = e + refraction_correction_deg(e, standard);
        EXPECT_LT(apparent, last) << e;
        EXPECT_LT(last - apparent, 0.02) << e;  // no jump: 0.01 degree steps move it < 0.02
        last = apparent;
    }
    // Proportional to pressure, zero in vacuum, and small high up.
    EXPECT_NEAR(refraction_correction_deg(10.0, {505.0, 10.0}), 0.5 * refraction_correction_deg(10.0, standard), 1e-12);
    EXPECT_EQ(refraction_correction_deg(10.0, {0.0, 10.0}), 0.0);
    EXPECT_LT(refraction_correction_deg(89.0, standard), 0.0003);
}

TEST(SunPosition, StandardAtmosphere) {
    const Atmosphere sea = Atmosphere::standard_at(0.0);
    EXPECT_NEAR(sea.pressure_hpa, 1013.25, 1e-9);
    EXPECT_NEAR(sea.temperature_c, 15.0, 1e-9);
    // ICAO tables: 795.0 hPa and 2.0 C at 2000 m.
    const Atmosphere high = Atmosphere::standard_at(2000.0);
    EXPECT_NEAR(high.pressure_hpa, 795.0, 0.1);
    EXPECT_NEAR(high.temperature_c, 2.0, 1e-9);
}

TEST(SunPosition, RejectsAbsurdInput) {
    SunPositionInput in = published_example();
    in.observer.latitude_deg = 91.0;
    EXPECT_THROW(sun_position(in), InputError);
    in = published_example();
    in.atmosphere.pressure_hpa = -1.0;
    EXPECT_THROW(sun_position(in), InputError);
    in = published_example();
    in.delta_t_s = 1e5;
    EXPECT_THROW(sun_position(in), InputError);
    in = published_example();
    in.observer.longitude_deg = std::nan("");
    EXPECT_THROW(sun_position(in), InputError);
    // Longitudes wrap: 254.8214 E is 105.1786 W.
    in = published_example();
    in.observer.longitude_deg += 360.0;
    EXPECT_NEAR(sun_position(in).azimuth_deg, 194.34024, 0.001);
}

}  // namespace
}  // namespace ts::light
