#pragma once
// ISO 8601 durations and START/END/STEP intervals, for `relight --times`: a list of instants
// from START to END inclusive, STEP apart.
#include <chrono>
#include <cstddef>
#include <string_view>
#include <vector>

#include "core/light/utc_time.hpp"

namespace ts::light {

// Parses an ISO 8601 duration of fixed length: PnW, or P[nD][T[nH][nM][nS]] such as PT1H,
// PT15M, P1DT12H, PT0.5S (a decimal fraction is allowed on the last component). Years and
// months are rejected: they have no fixed length. The result must be positive.
// Throws ts::InputError("<text>: problem").
std::chrono::microseconds parse_iso_duration(std::string_view text);

// Parses START/END/STEP (two ISO 8601 date-times with zones, then a duration) into
// START, START+STEP, ... up to END inclusive. END before START, or more than max_count
// instants (a typo such as PT1S over a year), throws ts::InputError.
std::vector<UtcTime> parse_time_interval(std::string_view text, std::size_t max_count = 100000);

}  // namespace ts::light
