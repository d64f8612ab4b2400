#include "core/light/time_interval.hpp"

#include <gtest/gtest.h>

#include "core/util/error.hpp"

namespace ts::light {
namespace {

using namespace std::chrono;

TEST(IsoDuration, ParsesFixedLengthDurations) {
    EXPECT_EQ(parse_iso_duration("PT1H"), hours(1));
    EXPECT_EQ(parse_iso_duration("PT15M"), minutes(15));
    EXPECT_EQ(parse_iso_duration("PT30S"), seconds(30));
    EXPECT_EQ(parse_iso_duration("PT0.5S"), milliseconds(500));
    EXPECT_EQ(parse_iso_duration("PT1.5H"), minutes(90));
    EXPECT_EQ(parse_iso_duration("P1D"), hours(24));
    EXPECT_EQ(parse_iso_duration("P2W"), days(14));
    EXPECT_EQ(parse_iso_duration("P1DT12H30M"), hours(36) + minutes(30));
    EXPECT_EQ(parse_iso_duration("PT1H1M1S"), seconds(3661));
}

TEST(IsoDuration, RejectsGarbage) {
    for (const char* bad : {"", "1H", "P", "PT", "PT1", "P1H", "PT1D", "P1M", "P1Y", "PT1M1H", "PT1.5H30M", "PT0S",
                            "PTxH", "PT1..5S", "PT.5S", "P1DT", "PT1H1H"}) {
        EXPECT_THROW(parse_iso_duration(bad), InputError) << bad;
    }
}

TEST(TimeInterval, ListsStartToEndInclusive) {
    const auto times = parse_time_interval("2024-06-21T04:00:00Z/2024-06-21T20:00:00Z/PT1H");
    ASSERT_EQ(times.size(), 17u);
    EXPECT_EQ(times.front(), parse_utc_time("2024-06-21T04:00:00Z"));
    EXPECT_EQ(times.back(), parse_utc_time("2024-06-21T20:00:00Z"));
    EXPECT_EQ(times[1] - times[0], hours(1));
}

TEST(TimeInterval, StopsBeforeOvershootingEnd) {
    const auto times = parse_time_interval("2024-06-21T12:00Z/2024-06-21T13:00Z/PT25M");
    ASSERT_EQ(times.size(), 3u);  // 12:00, 12:25, 12:50
    EXPECT_EQ(times.back(), parse_utc_time("2024-06-21T12:50Z"));
}

TEST(TimeInterval, OffsetsConvertToUtc) {
    const auto times = parse_time_interval("2024-06-21T14:00+02:00/2024-06-21T12:30Z/PT15M");
    ASSERT_EQ(times.size(), 3u);
    EXPECT_EQ(times.front(), parse_utc_time("2024-06-21T12:00Z"));
}

TEST(TimeInterval, SingleInstantWhenStartIsEnd) {
    EXPECT_EQ(parse_time_interval("2024-06-21T12:00Z/2024-06-21T12:00Z/PT1H").size(), 1u);
}

TEST(TimeInterval, RejectsBadIntervals) {
    for (const char* bad : {"2024-06-21T12:00Z", "2024-06-21T12:00Z/PT1H", "2024-06-21T12:00Z/2024-06-21T13:00Z",
                            "2024-06-21T13:00Z/2024-06-21T12:00Z/PT1H", "2024-06-21T12:00Z/2024-06-21T13:00Z/PT1H/x",
                            "garbage/2024-06-21T13:00Z/PT1H", "2024-06-21T12:00Z/2024-06-21T13:00Z/P1M"}) {
        EXPECT_THROW(parse_time_interval(bad), InputError) << bad;
    }
    // A step so short the list would be huge.
    EXPECT_THROW(parse_time_interval("2024-01-01T00:00Z/2025-01-01T00:00Z/PT1S"), InputError);
    EXPECT_EQ(parse_time_interval("2024-01-01T00:00Z/2024-01-01T00:10Z/PT1S", 601).size(), 601u);
}

}  // namespace
}  // namespace ts::light
