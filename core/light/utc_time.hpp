#pragma once
// UTC instants and their ISO 8601 spelling. One type for every command that takes a time
// (`sun --time`, `render --time`, `relight --times`), so they all accept the same strings.
#include <chrono>
#include <string>
#include <string_view>

namespace ts::light {

// An instant in UTC on the proleptic Gregorian calendar (ISO 8601's calendar), to the
// microsecond. Leap seconds are not counted (POSIX time), which is what UT-based sun
// formulas want: UTC and UT1 never differ by more than 0.9 s.
using UtcTime = std::chrono::sys_time<std::chrono::microseconds>;

// Parses an ISO 8601 date-time in extended format with an explicit zone:
//   2024-06-21T12:00:00Z, 2024-06-21T14:00:00+02:00, 2024-06-21T12:00:00.250Z,
//   2024-06-21T12:00Z (seconds optional), offsets +HH:MM, +HHMM or +HH; 'T' may be 't' or a space.
// A time without Z or an offset is rejected: local time is ambiguous and would silently move
// the sun by hours. Fractional seconds beyond microseconds are rounded to the microsecond.
// Throws ts::InputError("<text>: problem") on anything else.
UtcTime parse_utc_time(std::string_view text);

// The instant as YYYY-MM-DDTHH:MM:SS[.ffffff]Z (fraction only when non-zero, trailing zeros cut).
std::string format_utc_time(UtcTime t);

// Julian day (UT) of the instant: days since -4712-01-01 12:00 on the Julian calendar.
// Computed from the Unix epoch (JD 2440587.5), so it agrees with the SPA's calendar formula
// for every Gregorian date (after 1582-10-15).
double julian_day(UtcTime t);

// The instant as a decimal year (2024.5 is about 2024-07-02), for slowly varying models such as delta T.
double decimal_year(UtcTime t);

}  // namespace ts::light
