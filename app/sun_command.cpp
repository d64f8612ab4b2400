// `terrashade sun --time ISO8601 --lat LAT --lon LON [...] [--json]`: where the sun is, by the
// NREL SPA (core/light/sun_position.hpp): azimuth clockwise from north, topocentric zenith and
// elevation with refraction.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "app/command.hpp"
#include "core/light/sun_position.hpp"
#include "core/light/utc_time.hpp"
#include "core/util/error.hpp"

namespace ts::app {

namespace {

struct SunOptions {
    std::string time;
    double lat = NAN, lon = NAN, height_m = 0.0;
    double pressure_hpa = NAN, temperature_c = NAN, delta_t_s = NAN;  // NAN: not given
    bool json = false;
};

// An absurd value is bad usage: one line naming the flag.
void require_range(const char* flag, double v, double lo, double hi, bool hi_inclusive = true) {
    if (!std::isfinite(v) || v < lo || (hi_inclusive ? v > hi : v >= hi)) {
        char problem[128];
        std::snprintf(problem, sizeof problem, "%g is outside [%g, %g%s", v, lo, hi, hi_inclusive ? "]" : ")");
        throw input_error(flag, problem);
    }
}

void run_sun(const SunOptions& o, bool pressure_given, bool temperature_given, bool delta_t_given) {
    light::SunPositionInput in;
    try {
        in.time = light::parse_utc_time(o.time);
    } catch (const InputError& e) {
        throw InputError(std::string("--time ") + e.what());
    }
    require_range("--lat", o.lat, -90.0, 90.0);
    require_range("--lon", o.lon, -180.0, 360.0, /*hi_inclusive=*/false);
    require_range("--height-m", o.height_m, -1000.0, 100000.0);
    in.observer = {o.lat, o.lon > 180.0 ? o.lon - 360.0 : o.lon, o.height_m};
    // Unless given, the air is the standard atmosphere's at the observer's height.
    in.atmosphere = light::Atmosphere::standard_at(o.height_m);
    if (pressure_given) {
        require_range("--pressure-hpa", o.pressure_hpa, 0.0, 1200.0);
        in.atmosphere.pressure_hpa = o.pressure_hpa;
    }
    if (temperature_given) {
        require_range("--temperature-c", o.temperature_c, -100.0, 70.0);
        in.atmosphere.temperature_c = o.temperature_c;
    }
    if (delta_t_given) {
        require_range("--delta-t", o.delta_t_s, -8000.0, 8000.0);
        in.delta_t_s = o.delta_t_s;
    }
    const light::SunPosition s = light::sun_position(in);
    const std::string utc = light::format_utc_time(in.time);
    if (o.json) {
        nlohmann::ordered_json j;
        j["azimuth_deg"] = s.azimuth_deg;
        j["zenith_deg"] = s.zenith_deg;
        j["elevation_deg"] = s.elevation_deg;
        j["elevation_unrefracted_deg"] = s.elevation_unrefracted_deg;
        j["declination_deg"] = s.topocentric_declination_deg;
        j["earth_sun_distance_au"] = s.earth_sun_distance_au;
        j["time_utc"] = utc;
        j["lat_deg"] = o.lat;
        j["lon_deg"] = o.lon;
        j["height_m"] = o.height_m;
        j["pressure_hpa"] = in.atmosphere.pressure_hpa;
        j["temperature_c"] = in.atmosphere.temperature_c;
        j["delta_t_s"] = s.delta_t_s;
        std::cout << j.dump(2) << "\n";
        return;
    }
    std::printf("azimuth     %10.5f deg  (clockwise from north)\n", s.azimuth_deg);
    std::printf("zenith      %10.5f deg  (topocentric, with refraction)\n", s.zenith_deg);
    std::printf("elevation   %10.5f deg  (%.5f deg before refraction)\n", s.elevation_deg, s.elevation_unrefracted_deg);
    std::printf("time        %s (UTC)\n", utc.c_str());
    std::printf("observer    lat %.6f, lon %.6f, height %.2f m\n", o.lat, o.lon, o.height_m);
    std::printf("atmosphere  %.2f hPa, %.2f C%s\n", in.atmosphere.pressure_hpa, in.atmosphere.temperature_c,
                pressure_given || temperature_given ? "" : " (standard atmosphere at that height)");
    std::printf("delta T     %.3f s%s\n", s.delta_t_s, delta_t_given ? "" : " (Espenak-Meeus model)");
}

}  // namespace

void add_sun_command(CLI::App& root) {
    auto opts = std::make_shared<SunOptions>();
    CLI::App* cmd = root.add_subcommand(
        "sun",
        "Where the sun is at a UTC time and place (NREL Solar Position Algorithm, +-0.0003 deg): azimuth in "
        "degrees clockwise from north, topocentric zenith and elevation with atmospheric refraction.");
    cmd->add_option("--time", opts->time, "ISO 8601 time with a zone: 2024-06-21T12:00:00Z or 2024-06-21T14:00+02:00")
        ->required();
    cmd->add_option("--lat", opts->lat, "Latitude in degrees, north positive, [-90, 90]")->required();
    cmd->add_option("--lon", opts->lon, "Longitude in degrees, east positive, [-180, 360)")->required();
    cmd->add_option("--height-m", opts->height_m, "Observer height above the ellipsoid in metres")
        ->capture_default_str();
    CLI::Option* pressure = cmd->add_option("--pressure-hpa", opts->pressure_hpa,
                                            "Air pressure in hPa for refraction (default: standard atmosphere at "
                                            "--height-m; 0 turns refraction off)");
    CLI::Option* temperature = cmd->add_option("--temperature-c", opts->temperature_c,
                                               "Air temperature in C for refraction (default: standard atmosphere)");
    CLI::Option* delta_t = cmd->add_option("--delta-t", opts->delta_t_s,
                                           "TT - UT1 in seconds (default: Espenak-Meeus polynomial for the date)");
    cmd->add_flag("--json", opts->json, "Print one JSON object (azimuth_deg, zenith_deg, elevation_deg, inputs)");
    cmd->callback([opts, pressure, temperature, delta_t] {
        run_sun(*opts, pressure->count() > 0, temperature->count() > 0, delta_t->count() > 0);
    });
}

}  // namespace ts::app
