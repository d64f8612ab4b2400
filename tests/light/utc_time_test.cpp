#include "core/light/utc_time.hpp"

#include <gtest/gtest.h>

#include "core/util/error.hpp"

namespace ts::light {
namespace {

using namespace std::chrono;

TEST(UtcTime, ParsesZoneFormsToTheSameInstant) {
    const UtcTime noon = sys_days(2024y / June / 21) + 12h;
    EXPECT_EQ(parse_utc_time("2024-06-21T12:00:00Z"), noon);
    EXPECT_EQ(parse_utc_time("2024-06-21t12:00:00z"), noon);
    EXPECT_EQ(parse_utc_time("2024-06-21 12:00:00Z"), noon);
    EXPECT_EQ(parse_utc_time("2024-06-21T12:00Z"), noon);
    EXPECT_EQ(parse_utc_time("2024-06-21T14:00:00+02:00"), noon);
    EXPECT_EQ(parse_utc_time("2024-06-21T14:00:00+0200"), noon);
    EXPECT_EQ(parse_utc_time("2024-06-21T14:00:00+02"), noon);
    EXPECT_EQ(parse_utc_time("2024-06-21T06:30:00-05:30"), noon);
    EXPECT_EQ(parse_utc_time("2024-06-22T00:00:00+12:00"), noon);  // crosses the date line
}

TEST(UtcTime, FractionalSeconds) {
    const UtcTime noon = sys_days(2024y / June / 21) + 12h;
    EXPECT_EQ(parse_utc_time("2024-06-21T12:00:00.25Z"), noon + 250ms);
    EXPECT_EQ(parse_utc_time("2024-06-21T12:00:00,5Z"), noon + 500ms);
    EXPECT_EQ(parse_utc_time("2024-06-21T12:00:00.1234567Z"), noon + 123457us);  // rounded
}

TEST(UtcTime, RejectsGarbageAndAmbiguity) {
    for (const char* bad : {"", "now", "2024-06-21", "2024-06-21T12:00:00", "2024-13-01T00:00Z", "2023-02-29T00:00Z",
                            "2024-06-31T00:00Z", "2024-06-21T24:00:00Z", "2024-06-21T12:60Z", "2024-06-21T12:00:61Z",
                            "2024-06-21T12:00:00.Z", "2024-06-21T12:00:00+25:00", "2024-06-21T12:00:00Zjunk",
                            "24-06-21T12:00Z", "2024/06/21T12:00Z", "2024-06-21T12:00:00 Z"}) {
        EXPECT_THROW(parse_utc_time(bad), InputError) << bad;
    }
    // A leap day exists in leap years.
    EXPECT_NO_THROW(parse_utc_time("2024-02-29T00:00Z"));
}

TEST(UtcTime, ErrorNamesTheInput) {
    try {
        parse_utc_time("2024-06-21T12:00:00");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("2024-06-21T12:00:00: "), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("zone"), std::string::npos) << e.what();
    }
}

TEST(UtcTime, FormatsRoundTrip) {
    EXPECT_EQ(format_utc_time(parse_utc_time("2003-10-17T12:30:30-07:00")), "2003-10-17T19:30:30Z");
    EXPECT_EQ(format_utc_time(parse_utc_time("2024-06-21T12:00:00.250Z")), "2024-06-21T12:00:00.25Z");
    EXPECT_EQ(format_utc_time(parse_utc_time("1969-12-31T23:59:59.5Z")), "1969-12-31T23:59:59.5Z");
}

TEST(UtcTime, JulianDay) {
    // J2000.0 is JD 2451545.0; the SPA example's JD is printed as 2452930.312847.
    EXPECT_DOUBLE_EQ(julian_day(parse_utc_time("2000-01-01T12:00:00Z")), 2451545.0);
    EXPECT_NEAR(julian_day(parse_utc_time("2003-10-17T19:30:30Z")), 2452930.312847, 1e-6);
    // Meeus, Astronomical Algorithms, example 7.a: 1957-10-04.81 = JD 2436116.31.
    EXPECT_NEAR(julian_day(parse_utc_time("1957-10-04T19:26:24Z")), 2436116.31, 1e-6);
}

TEST(UtcTime, DecimalYear) {
    EXPECT_DOUBLE_EQ(decimal_year(parse_utc_time("2024-01-01T00:00:00Z")), 2024.0);
    EXPECT_NEAR(decimal_year(parse_utc_time("2023-07-02T12:00:00Z")), 2023.5, 1e-9);
}

}  // namespace
}  // namespace ts::light
