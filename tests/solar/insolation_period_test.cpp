#include "core/solar/insolation_period.hpp"

#include <chrono>

#include <gtest/gtest.h>

#include "core/util/error.hpp"

namespace ts::solar {
namespace {

TEST(InsolationPeriod, MonthsOfALeapYearOnTheLocalClock) {
    const auto periods = make_periods({2024, 1, 1}, {2024, 12, 31}, PeriodSplit::month, 15.0);
    ASSERT_EQ(periods.size(), 12u);
    EXPECT_EQ(periods[1].label, "2024-02");
    EXPECT_EQ(std::chrono::duration_cast<std::chrono::hours>(periods[1].end - periods[1].begin).count(), 29 * 24);
    // Midnight at 15 deg east is 23:00 UTC the day before.
    EXPECT_EQ(light::format_utc_time(periods[0].begin), "2023-12-31T23:00:00Z");
    const auto year = make_periods({2024, 1, 1}, {2024, 12, 31}, PeriodSplit::year, 0.0);
    ASSERT_EQ(year.size(), 1u);
    EXPECT_EQ(year[0].label, "2024");
}

TEST(InsolationPeriod, PartialUnitsAndDays) {
    const auto p = make_periods({2023, 12, 30}, {2024, 1, 2}, PeriodSplit::year, 0.0);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[0].label, "2023-12-30..2023-12-31");
    const auto d = make_periods({2024, 2, 28}, {2024, 3, 1}, PeriodSplit::day, 0.0);
    ASSERT_EQ(d.size(), 3u);
    EXPECT_EQ(d[1].label, "2024-02-29");
}

TEST(InsolationPeriod, BadDatesAreInputErrors) {
    EXPECT_THROW(parse_calendar_date("2023-02-29", "--from"), InputError);
    EXPECT_THROW(parse_calendar_date("2023-1-01", "--from"), InputError);
    EXPECT_THROW(parse_period_split("week"), InputError);
    EXPECT_THROW(make_periods({2024, 3, 2}, {2024, 3, 1}, PeriodSplit::day, 0.0), InputError);
    EXPECT_EQ(local_day(local_midnight({2024, 12, 31}, 0.0), 0.0).day_of_year, 366);
}

}  // namespace
}  // namespace ts::solar
