#pragma once
// The periods an insolation map sums over: a year, a range of dates, split by year, month or
// day. Days are counted on the local mean solar clock of one longitude (the DEM's centre), so a
// day's sums hold one whole day of sun wherever the DEM is; the clock's offset from UTC is
// longitude / 15 hours.
#include <string>
#include <vector>

#include "core/light/utc_time.hpp"

namespace ts::solar {

struct CalendarDate {
    int year = 2000, month = 1, day = 1;
};

struct InsolationPeriod {
    light::UtcTime begin, end;  // [begin, end)
    std::string label;          // "2024", "2024-03", "2024-03-21", "2024-03-01..2024-05-31"
};

enum class PeriodSplit { year, month, day };

// "YYYY-MM-DD" (a real Gregorian date, years 1..9999); throws ts::InputError("<what>: ...").
CalendarDate parse_calendar_date(const std::string& text, const std::string& what);
// "year" | "month" | "day"; throws ts::InputError naming the choices.
PeriodSplit parse_period_split(const std::string& text);

// Midnight starting `date` on the mean solar clock of `longitude_deg`, as a UTC instant.
light::UtcTime local_midnight(const CalendarDate& date, double longitude_deg);

// The periods from `first` to `last` inclusive (whole days), split at the boundaries of
// `split`; a period that spans the whole range of a split unit gets that unit's label.
// Throws ts::InputError when last is before first.
std::vector<InsolationPeriod> make_periods(const CalendarDate& first, const CalendarDate& last, PeriodSplit split,
                                           double longitude_deg);

// The calendar date and month (0..11) and day of year (1..366) of an instant on the mean solar
// clock of `longitude_deg`.
struct LocalDay {
    int month0 = 0;
    int day_of_year = 1;
};
LocalDay local_day(light::UtcTime t, double longitude_deg);

}  // namespace ts::solar
