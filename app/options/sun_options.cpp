#include "app/options/sun_options.hpp"
#include "app/options/within_range.hpp"

namespace ts::app {

CLI::Validator azimuth_range() { return within(kMinAzimuth, kMaxAzimuth); }

void add_time_option(CLI::App& cmd, std::string& time) {
    cmd.add_option("--time", time,
                   "UTC instant of the sun, ISO 8601 with a zone (e.g. 2025-06-21T12:00:00+02:00), placed for the "
                   "DEM's centre");
}

void add_sun_options(CLI::App& cmd, std::string& time, std::optional<double>& azimuth_deg,
                     std::optional<double>& elevation_deg) {
    add_time_option(cmd, time);
    cmd.add_option("--sun-azimuth", azimuth_deg, "Sun azimuth, degrees clockwise from north, 0..360 (instead of --time)")
        ->check(azimuth_range());
    cmd.add_option("--sun-elevation", elevation_deg, "Sun elevation above the horizon, degrees, -90..90")
        ->check(within(-90.0, 90.0));
}

}  // namespace ts::app
