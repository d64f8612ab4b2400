#pragma once
// The options `tiles` and `bench tiles` share: zooms, tile size, style and light
// (app/tiles_command.cpp, app/bench/bench_tiles_command.cpp).
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "app/options/colors_option.hpp"
#include "app/options/insolation_options.hpp"
#include "app/options/sky_light_option.hpp"

#include "core/dem/dem.hpp"
#include "core/tiles/tile_export.hpp"

namespace ts::app {

struct TilesArgs {
    std::string zoom;  // Z or Z0-Z1
    bool zoom_given = false;  // --zoom was on the command line (an empty one is an error, not zoom 0)
    int tile_size = 256;
    std::string style = "relief";
    std::string time;
    std::optional<double> sun_azimuth, sun_elevation;
    std::string sky = "clear";
    ColorsArgs colors;  // --colors, --snow-line (style color)
    double z_factor = 1.0;
    std::string exaggeration = "auto";
    int directions = 16;
    render::BounceSettings bounce;  // --bounces, --bounce-directions, --bounce-radius
    SkyLightArgs sky_light;         // --sky-light, --sky-sectors (relief, color)
    int block_texels = 2048;
    int block_halo = 256;
    std::string far_field = "balanced";
    std::string resampling = "cubic";
    double relief_contrast = 1.0;
    int light_directions = 128;  // lightable
    int light_components = 6;    // lightable
    int level_bias = 0;
    int threads = 0;
    bool verbose = false;  // -v: what each zoom was shaded from
    // --max-error E: each zoom's --directions chosen for a relative radiance error E
    // (core/quality/radiance_quality.hpp); --directions given too conflicts.
    std::optional<double> max_error;
    bool directions_given = false;
    // --style insolation: the days and the sky of the sum, the quantity and its ramp.
    InsolationArgs insolation;
    std::string quantity = "global";
    std::string ramp;  // "LO,HI" in the quantity's unit; empty: default_insolation_ramp
};

// `with_zoom`: add --zoom (bench tiles fixes its own).
void add_tiles_options(CLI::App& cmd, TilesArgs& args, bool with_zoom = true);
// Parses and checks every flag (ts::InputError); the sun from --time is set once the DEM is read.
tiles::TileJob tile_job(const TilesArgs& args);
// --max-error: once the DEM and the sun are known, each zoom's directions (the cheapest
// predicted under E for that zoom's level and vertical scale) into job.directions_by_zoom, with
// one line per group of zooms saying what and why. Does nothing without --max-error or for a
// style without visibility.
void choose_tile_directions(const TilesArgs& args, const dem::Dem& dem, tiles::TileJob& job);
// --style insolation: once the DEM is read (and the output opened), the sun tables of its days
// for the whole DEM (shared by every zoom) and the default ramp into job.shading.insolation.
// Does nothing for the other styles.
void set_tile_insolation(const TilesArgs& args, const dem::Dem& dem, tiles::TileJob& job);
// "Z" or "Z0-Z1" -> (z0, z1), each 0..24 with z0 <= z1.
void parse_zoom_range(const std::string& text, int& z0, int& z1);

}  // namespace ts::app
