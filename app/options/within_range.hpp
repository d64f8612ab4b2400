#pragma once
// One range check for every numeric option of every command, so that a value out of range reads
// the same everywhere: "--azimuth: must be within 0..360, got 400". CLI11's own CLI::Range prints
// "Value 400 not in range 0.000000 to 360.000000", whose six decimals say nothing to a user.
#include <CLI/CLI.hpp>

namespace ts::app {

// The check of an option whose value must lie in [lo, hi]; its help reads "in LO..HI".
CLI::Validator within(double lo, double hi);

}  // namespace ts::app
