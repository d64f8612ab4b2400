#pragma once
// The sun's place, one declaration for every command that lights terrain with it: --time, or
// --sun-azimuth and --sun-elevation (hillshade calls them --azimuth and --altitude, with the same
// azimuth range). Azimuths are degrees clockwise from north, 0..360.
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace ts::app {

inline constexpr double kMinAzimuth = 0.0, kMaxAzimuth = 360.0;

// --time alone (fly, whose sun is always a time's).
void add_time_option(CLI::App& cmd, std::string& time);
// --time, --sun-azimuth 0..360 and --sun-elevation -90..90.
void add_sun_options(CLI::App& cmd, std::string& time, std::optional<double>& azimuth_deg,
                     std::optional<double>& elevation_deg);
// An azimuth option's check, 0..360 (hillshade --azimuth).
CLI::Validator azimuth_range();

}  // namespace ts::app
