#include "app/tiles_options.hpp"

#include "app/options/bounce_option.hpp"
#include "app/options/directions_option.hpp"
#include "app/options/max_error_option.hpp"
#include "app/options/sky_option.hpp"
#include "app/options/sun_options.hpp"
#include "app/options/threads_option.hpp"
#include "app/options/verbose_option.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <string_view>
#include <vector>

#include "app/dem_sun_tables.hpp"
#include "core/light/utc_time.hpp"
#include "core/tiles/tile_insolation.hpp"
#include "core/quality/radiance_quality.hpp"
#include "core/quality/visibility_quality.hpp"
#include "core/tiles/dem_level.hpp"
#include "core/visibility/visibility_grid.hpp"
#include "core/tiles/web_mercator.hpp"
#include "core/util/error.hpp"

namespace ts::app {

void parse_zoom_range(const std::string& text, int& z0, int& z1) {
    auto number = [&](std::string_view s, int& out) {
        const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
        return !s.empty() && ec == std::errc() && p == s.data() + s.size();
    };
    const auto dash = text.find('-', 1);
    const std::string_view all(text);
    const bool ok = dash == std::string::npos ? number(all, z0) && number(all, z1)
                                              : number(all.substr(0, dash), z0) && number(all.substr(dash + 1), z1);
    if (!ok) throw InputError("--zoom " + text + ": give Z or Z0-Z1 (e.g. 8-12)");
    if (z0 < 0 || z1 < 0 || z0 > tiles::kMaxZoom || z1 > tiles::kMaxZoom)
        throw InputError("--zoom " + text + ": zooms are 0.." + std::to_string(tiles::kMaxZoom));
    if (z1 < z0) throw InputError("--zoom " + text + ": Z1 must not be below Z0");
}

void add_tiles_options(CLI::App& cmd, TilesArgs& a, bool with_zoom) {
    if (with_zoom)
        cmd.add_option("--zoom", a.zoom, "Zoom levels Z0-Z1 (or one zoom Z), 0..24")
            ->required()
            ->each([&a](const std::string&) { a.zoom_given = true; });
    cmd.add_option("--tile-size", a.tile_size, "Tile size in pixels: 256 or 512 (a 512-px tile at z shows the "
                                               "pixels of four 256-px tiles at z+1)")
        ->capture_default_str();
    cmd.add_option("--style", a.style, tiles::tile_style_names(" | ") + " (docs/tiles.md)")
        ->capture_default_str();
    add_sun_options(cmd, a.time, a.sun_azimuth, a.sun_elevation);  // neither: azimuth 315, elevation 45
    add_sky_option(cmd, a.sky);  // relief and color
    add_colors_options(cmd, a.colors);  // color
    cmd.add_option("--z-factor", a.z_factor, "Vertical exaggeration on top of the zoom's (> 0)")->capture_default_str();
    cmd.add_option("--exaggeration", a.exaggeration,
                   "auto (E = 2^(max(0, 12 - zoom)/3), zooms past the DEM's native one keeping its value, raised "
                   "below zoom 12 up to min(4 E, E^2) where the relief is too gentle to read; docs/tiles.md) or a "
                   "number replacing it at every zoom")
        ->capture_default_str();
    add_directions_option(cmd, a.directions, &a.directions_given);  // relief, svf, color, insolation
    add_max_error_option(cmd, a.max_error);                          // relief, color: per zoom
    cmd.add_option("--block-texels", a.block_texels,
                   "relief/svf/color: levels larger than this many texels a side are shaded in blocks of it, "
                   "bounding memory (0 = whole levels; docs/tiles.md)")
        ->capture_default_str();
    cmd.add_option("--block-halo", a.block_halo,
                   "relief/svf/color: texels around each block it is shaded with (the reach of cast shadows and of the "
                   "sky's exact horizons)")
        ->capture_default_str();
    cmd.add_option("--resampling", a.resampling,
                   "between source texels (relief/svf/color: the shading; hillshade/multidirectional: the heights), "
                   "cubic (Catmull-Rom: crisp, no bands along the texel rows where a zoom magnifies its DEM level) or "
                   "bilinear")
        ->capture_default_str();
    cmd.add_option("--relief-contrast", a.relief_contrast,
                   "relief: the shading's contrast in stops about open flat ground, 0.25..4 (1 = physical; 1.5 for "
                   "print: a slope a stop brighter than the flat becomes 1.5 stops brighter, a shadow as much darker)")
        ->capture_default_str();
    cmd.add_option("--light-directions", a.light_directions,
                   "lightable: horizon azimuths stored per pixel for the sun's shadows at any instant, a multiple of 4 "
                   "(more: shadow rims closer to relief's, larger tiles; docs/web-map.md)")
        ->capture_default_str();
    cmd.add_option("--light-components", a.light_components,
                   "lightable: principal components of the sky's transfer kept per tile, 1..9 (docs/web-map.md)")
        ->capture_default_str();
    cmd.add_option("--level-bias", a.level_bias,
                   "Shade each zoom from the DEM level matching its pixels moved by B, -4..4: > 0 coarser (faster, "
                   "softer), < 0 finer (slower, aliased); docs/tiles.md")
        ->capture_default_str();
    cmd.add_option("--far-field", a.far_field,
                   "relief/svf/color in blocks: the sky's terrain beyond the halo, exact (the whole level swept per "
                   "block: slow) or marched over coarser levels: fast, balanced, fine, finest")
        ->capture_default_str();
    add_insolation_options(cmd, a.insolation);  // insolation
    a.insolation.added.push_back(
        cmd.add_option("--quantity", a.quantity,
                       "insolation: global, beam, diffuse, reflected (kWh/m2 over the days) or sun-hours (h)")
            ->capture_default_str());
    a.insolation.added.push_back(cmd.add_option(
        "--ramp", a.ramp,
        "insolation: the colour ramp's ends LO,HI in the quantity's unit (default: from open flat ground's value; "
        "docs/tiles.md)"));
    add_bounce_options(cmd, a.bounce);  // relief, color, lightable
    add_sky_light_options(cmd, a.sky_light);  // relief, color
    add_threads_option(cmd, a.threads);
    add_verbose_flag(cmd, a.verbose);
}

namespace {

// "LO,HI" with LO < HI, both finite.
tiles::RampEnds parse_ramp(const std::string& text) {
    const auto comma = text.find(',');
    double lo = 0, hi = 0;
    auto number = [](std::string_view s, double& out) {
        const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
        return !s.empty() && ec == std::errc() && p == s.data() + s.size() && std::isfinite(out);
    };
    const std::string_view all(text);
    if (comma == std::string::npos || !number(all.substr(0, comma), lo) || !number(all.substr(comma + 1), hi) || !(lo < hi))
        throw InputError("--ramp " + text + ": give LO,HI with LO < HI (e.g. 800,2400 for kWh/m2)");
    return {float(lo), float(hi)};
}

// --quantity: global, beam, diffuse, reflected or sun-hours -> solar::Quantity.
int parse_insolation_quantity(const std::string& text) {
    for (int q = 0; q < solar::kQuantities; ++q)
        if (text == tiles::insolation_quantity_name(q)) return q;
    throw InputError("--quantity " + text + ": global, beam, diffuse, reflected or sun-hours");
}

// The --style insolation checks that need no DEM.
void check_insolation_style(const TilesArgs& a, tiles::TileShading& s) {
    const bool insolation = s.style->name() == "insolation";
    if (!insolation) {
        if (a.insolation.any_given())
            throw InputError("--year, --from/--to, --linke, --albedo, --quantity, --ramp ... are for --style insolation, "
                             "not " + a.style);
        return;
    }
    if (!a.time.empty() || a.sun_azimuth || a.sun_elevation)
        throw InputError("--style insolation sums every sun of its days (--year or --from/--to): --time and "
                         "--sun-azimuth/--sun-elevation do not apply");
    if (a.sky != "clear") throw InputError("--style insolation: its sky is ESRA's clear sky; --sky does not apply");
    if (a.z_factor != 1.0 || (a.exaggeration != "auto" && s.exaggeration != 1.0))
        throw InputError("--style insolation sums the sun over the true heights: --z-factor and --exaggeration do not "
                         "apply");
    s.exaggeration = 1.0;
    const auto [first, last] = insolation_dates(a.insolation);
    solar::InsolationSettings st = insolation_settings(a.insolation);
    st.periods = solar::make_periods(first, last, solar::PeriodSplit::year, 0.0);
    solar::check_settings(st);
    auto ins = std::make_shared<tiles::TileInsolation>();
    ins->quantity = parse_insolation_quantity(a.quantity);
    ins->reflection = a.insolation.reflection;
    if (!a.ramp.empty()) {
        const tiles::RampEnds ramp = parse_ramp(a.ramp);
        ins->lo = ramp.lo, ins->hi = ramp.hi;
    }
    // What changes the tiles' bytes, known before the DEM is read so that a conflicting job in
    // --out is refused before the sun tables are built (the default ramp follows from the DEM
    // and these).
    ins->describe = describe_insolation_sum(a.insolation) + " " + tiles::insolation_quantity_name(ins->quantity) +
                    " ramp " + (a.ramp.empty() ? std::string("auto") : a.ramp);
    s.insolation = std::move(ins);
    // The default of `insolation` (a tile set and a GeoTIFF of the same days then agree).
    if (!a.directions_given) s.directions = 64;
}

}  // namespace

void set_tile_insolation(const TilesArgs& a, const dem::Dem& dem, tiles::TileJob& job) {
    tiles::TileShading& s = job.shading;
    if (s.style->name() != "insolation") return;
    solar::InsolationSettings settings = insolation_settings(a.insolation);
    settings.azimuth_bins = 4 * s.directions;
    settings.svf_stride = 4;
    settings.threads = s.threads;
    const auto [first, last] = insolation_dates(a.insolation);
    settings.periods = solar::make_periods(first, last, solar::PeriodSplit::year, 0.0);
    solar::check_settings(settings);
    const DemSunTables sun = build_dem_sun_tables(dem, settings, first, last, solar::PeriodSplit::year, 0.05, 1000.0);
    auto ins = std::make_shared<tiles::TileInsolation>(*s.insolation);
    ins->model = sun.model;
    if (a.ramp.empty()) {
        const tiles::RampEnds ramp = tiles::default_insolation_ramp(*sun.model, ins->quantity);
        ins->lo = ramp.lo, ins->hi = ramp.hi;
    }
    s.insolation = std::move(ins);
    std::printf("insolation %s: sun tables in %.2f s; colour ramp %.4g..%.4g %s\n",
                tiles::insolation_quantity_name(s.insolation->quantity), sun.seconds, double(s.insolation->lo), double(s.insolation->hi),
                solar::quantity_unit(s.insolation->quantity));
    std::fflush(stdout);
}

tiles::TileJob tile_job(const TilesArgs& a) {
    tiles::TileJob job;
    if (!a.zoom.empty() || a.zoom_given) parse_zoom_range(a.zoom, job.z0, job.z1);
    job.tile_size = a.tile_size;
    tiles::TileShading& s = job.shading;
    s.style = &tiles::parse_tile_style(a.style);
    const bool by_angles = a.sun_azimuth || a.sun_elevation;
    if (!a.time.empty() && by_angles) throw InputError("tiles: give --time or --sun-azimuth/--sun-elevation, not both");
    if (!a.time.empty()) light::parse_utc_time(a.time);  // a malformed time fails before any work
    if (a.sun_azimuth) s.sun_azimuth_deg = *a.sun_azimuth;
    if (a.sun_elevation) s.sun_elevation_deg = *a.sun_elevation;
    s.sky = light::parse_sky_options(a.sky);
    if (s.style->colours_land()) {
        s.colors = color_design(a.colors);
    } else if (a.colors.colors != render::kDefaultPalette || a.colors.snow_line_m) {
        throw InputError("--colors and --snow-line colour --style color and lightable; " + a.style + " tiles are grey by design");
    }
    s.z_factor = a.z_factor;
    if (a.exaggeration != "auto") {
        double e = 0;
        const auto [p, ec] = std::from_chars(a.exaggeration.data(), a.exaggeration.data() + a.exaggeration.size(), e);
        if (ec != std::errc() || p != a.exaggeration.data() + a.exaggeration.size())
            throw InputError("--exaggeration " + a.exaggeration + ": auto or a number > 0");
        s.exaggeration = e;
    }
    if (a.max_error) {
        check_max_error(a.max_error, a.directions_given ? "--directions" : "");
        if (!s.style->takes_max_error())
            throw InputError("--max-error bounds the radiance of --style relief or color, not " + a.style);
    }
    s.directions = a.directions;
    s.bounce = a.bounce;
    // The browser relights lightable tiles through SH, with the sky the SH path takes, and the
    // bounce's sun part from T_b's SH (what the data tiles hold).
    s.sky_light = sky_light_settings(a.sky_light);
    if (s.style->data_tile()) {
        s.sky_light.mode = render::SkyLightSettings::Mode::sh;
        s.bounce.sun = render::BounceSettings::SunPart::sh;
    }
    check_bounce_options(s.bounce);
    s.block_texels = a.block_texels;
    s.block_halo_texels = a.block_halo;
    s.far_field = tiles::parse_far_field(a.far_field);
    s.resampling = tiles::parse_resampling(a.resampling);
    s.relief_contrast = a.relief_contrast;
    s.light_directions = a.light_directions;
    s.light_components = a.light_components;
    job.level_bias = a.level_bias;
    s.threads = a.threads;
    check_insolation_style(a, s);
    tiles::check_tile_job(job);
    return job;
}

void choose_tile_directions(const TilesArgs& a, const dem::Dem& dem, tiles::TileJob& job) {
    if (!a.max_error) return;
    job.shading.max_error = *a.max_error;  // and per block, for levels shaded in blocks
    std::map<int, double> level_roughness;  // mean tan slope of each level at vertical scale 1
    struct Group {
        int z0, z1;
        quality::RadianceChoice choice;
    };
    std::vector<Group> groups;
    for (int z = job.z0; z <= job.z1; ++z) {
        const tiles::ZoomShading zs = tiles::zoom_shading(dem, job, z + tiles::tile_size_shift(job.tile_size));
        if (!level_roughness.count(zs.level)) {
            const visibility::VisibilityGrid grid(zs.level == 0 ? dem : tiles::dem_level(dem, zs.level, job.shading.threads));
            level_roughness[zs.level] = quality::mean_tan_slope(grid.view());
        }
        quality::RadianceScene scene;
        scene.roughness = level_roughness[zs.level] * zs.vertical_scale;  // heights scale, so do their slopes
        scene.sun_elevations_deg = {job.shading.sun_elevation_deg};
        scene.exact_sun_available = false;  // tiles shade their sun with the sweep
        const quality::RadianceChoice c = quality::choose_radiance(*a.max_error, scene);
        job.directions_by_zoom[z] = c.directions;
        if (!groups.empty() && groups.back().choice.reason == c.reason) groups.back().z1 = z;
        else groups.push_back({z, z, c});
    }
    for (const Group& g : groups) {
        const std::string line = max_error_line(g.choice.reason);
        if (g.z0 == g.z1) std::printf("zoom %d: %s\n", g.z0, line.c_str());
        else std::printf("zooms %d-%d: %s\n", g.z0, g.z1, line.c_str());
    }
    std::fflush(stdout);
}

}  // namespace ts::app
