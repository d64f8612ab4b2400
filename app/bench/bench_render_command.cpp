// `terrashade bench render`: the renderer's map radiance against the ray-traced reference
// (core/render/reference_shading.hpp) with the same normals, materials, sky and BRDFs, for a
// morning, noon and evening sun on each DEM (docs/accuracy.md):
//  - radiance (luminance) on a random subset of texels (fixed seed): relative RMSE, the 99th
//    percentile of the relative error, and the relative bias;
//  - the sun-shadow mask (visible fraction < 0.5) over every texel: the renderer's sun
//    visibility (exact sweep in the sun's azimuth) against the raymarched one: intersection
//    over union.
// Its CSV feeds scripts/chart_render.py; docs/accuracy.md reads the numbers.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "app/io_plan.hpp"
#include "app/bench/bench_command.hpp"
#include "app/bench/csv_number.hpp"
#include "app/bench/error_stats.hpp"
#include "app/dem_input.hpp"
#include "core/dem/crop.hpp"
#include "core/light/sky.hpp"
#include "core/light/sun_position.hpp"
#include "core/light/utc_time.hpp"
#include "core/render/frame_renderer.hpp"
#include "core/material/material.hpp"
#include "core/quality/visibility_quality.hpp"
#include "core/render/reference_shading.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/util/angles.hpp"
#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"
#include "core/util/stopwatch.hpp"
#include "core/visibility/visibility_grid.hpp"
#include "app/options/within_range.hpp"

namespace ts::app {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct BenchRenderOptions {
    std::vector<std::string> dems;
    std::vector<std::string> times;  // ISO 8601; empty: morning/noon/evening of --date at each DEM
    std::string date = "2024-10-15";
    std::vector<double> solar_hours = {8.5, 12.0, 16.5};
    int samples = 1000;
    unsigned seed = 6;
    std::string sky = "clear";
    std::vector<int> directions = {32};
    std::vector<std::string> sun_shadows = {"sweep"};
    std::vector<std::string> terrain_transfers = {"exact"};
    // --suns AZ/EL,...: sun positions given directly (instead of times); --window N with
    // --window-at FX:FY,...: square windows of N texels placed at those fractions of the DEM.
    std::vector<std::string> suns;
    int window = 0;
    std::vector<std::string> window_at = {"0.5:0.5"};
    int azimuths = 720;
    bool no_curvature = false;
    int threads = 0;
    std::string csv;
};

struct Row {
    std::string dem, label, time;
    int col0 = 0, row0 = 0, width = 0, height = 0, samples = 0;
    int directions = 0;
    std::string sun_shadows, terrain_transfer;
    double mean_tan_slope = kNaN;  // quality::mean_tan_slope of the grid: what --max-error predicts from
    double state_s = kNaN;         // the one-time visibility + transfer
    double azimuth_deg = kNaN, elevation_deg = kNaN;
    double rel_rmse = kNaN, rel_p99 = kNaN, rel_bias = kNaN;
    double sun_lit_rel_rmse = kNaN, shadow_rel_rmse = kNaN;
    double iou = kNaN, mask_disagree = kNaN, sun_fraction_mae = kNaN, shadow_share = kNaN;
    double frame_ms = kNaN, sun_visibility_ms = kNaN, reference_sun_ms = kNaN, reference_s = kNaN;
};

double luminance(const glm::vec3& c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// The UTC instant of a local mean solar time (hours) on a date at a longitude.
light::UtcTime solar_time(const std::string& date, double hours, double lon_deg) {
    const light::UtcTime midnight = light::parse_utc_time(date + "T00:00:00Z");
    const double utc_hours = hours - lon_deg / 15.0;
    return midnight + std::chrono::microseconds(std::llround(utc_hours * 3600e6));
}

std::string label_of(double hours) {
    if (hours < 11.0) return "morning";
    if (hours <= 13.0) return "noon";
    return "evening";
}

void print_row(const Row& r) {
    std::printf("%-34s %-8s %7.1f %6.1f %6d %9.4f %9.4f %9.4f %8.4f %9.5f %8.1f %8.1f %8.1f %7.1f\n", r.dem.c_str(),
                r.label.c_str(), r.azimuth_deg, r.elevation_deg, r.samples, r.rel_rmse, r.rel_p99, r.rel_bias, r.iou,
                r.mask_disagree, r.frame_ms, r.sun_visibility_ms, r.reference_sun_ms, r.reference_s);
    std::fflush(stdout);
}

std::string csv_text(const std::vector<Row>& rows) {
    std::ostringstream out;
    out << "dem,label,time_utc,width,height,samples,sun_azimuth_deg,sun_elevation_deg,rel_rmse,rel_p99,rel_bias,"
           "sunlit_rel_rmse,shadow_rel_rmse,mask_iou,mask_disagree,sun_fraction_mae,shadow_share,frame_ms,"
           "sun_visibility_ms,"
           "reference_sun_ms,reference_s,col0,row0,directions,sun_shadows,mean_tan_slope,state_s,terrain_transfer\n";
    for (const Row& r : rows)
        out << r.dem << ',' << r.label << ',' << r.time << ',' << r.width << ',' << r.height << ',' << r.samples << ','
            << csv_number(r.azimuth_deg) << ',' << csv_number(r.elevation_deg) << ',' << csv_number(r.rel_rmse) << ',' << csv_number(r.rel_p99)
            << ',' << csv_number(r.rel_bias) << ',' << csv_number(r.sun_lit_rel_rmse) << ',' << csv_number(r.shadow_rel_rmse) << ','
            << csv_number(r.iou) << ',' << csv_number(r.mask_disagree) << ',' << csv_number(r.sun_fraction_mae) << ',' << csv_number(r.shadow_share)
            << ',' << csv_number(r.frame_ms) << ',' << csv_number(r.sun_visibility_ms) << ',' << csv_number(r.reference_sun_ms) << ','
            << csv_number(r.reference_s) << ',' << r.col0 << ',' << r.row0 << ',' << r.directions << ','
            << r.sun_shadows << ',' << csv_number(r.mean_tan_slope) << ',' << csv_number(r.state_s) << ','
            << r.terrain_transfer << '\n';
    return out.str();
}

// Random distinct non-void texels (fixed seed: the same subset every run).
std::vector<std::size_t> sample_texels(const terrain::HeightGrid& g, int samples, unsigned seed) {
    std::vector<std::size_t> valid;
    for (std::size_t i = 0; i < g.z.size(); ++i)
        if (!std::isnan(g.z[i])) valid.push_back(i);
    std::mt19937_64 rng(seed);
    const std::size_t n = std::min(valid.size(), std::size_t(std::max(0, samples)));
    for (std::size_t i = 0; i < n; ++i) {  // partial Fisher-Yates
        std::uniform_int_distribution<std::size_t> pick(i, valid.size() - 1);
        std::swap(valid[i], valid[pick(rng)]);
    }
    valid.resize(n);
    std::sort(valid.begin(), valid.end());
    return valid;
}

// One sun of the study: its label, time (empty for --suns) and position.
struct StudySun {
    std::string label, time;
    render::SunState sun;
};

std::vector<StudySun> study_suns(const BenchRenderOptions& o, const dem::Dem& dem) {
    std::vector<StudySun> out;
    for (const std::string& text : o.suns) {
        StudySun s;
        if (std::sscanf(text.c_str(), "%lf/%lf", &s.sun.azimuth_deg, &s.sun.elevation_deg) != 2)
            throw InputError("--suns " + text + ": give AZIMUTH/ELEVATION in degrees");
        s.label = "el" + text.substr(text.find('/') + 1);
        out.push_back(s);
    }
    if (!o.suns.empty()) return out;
    const glm::dvec2 centre = dem.georef.pixel_to_lonlat(dem.width * 0.5, dem.height * 0.5);
    const float centre_z = dem.at(dem.width / 2, dem.height / 2);
    std::vector<std::pair<std::string, light::UtcTime>> times;
    if (!o.times.empty()) {
        for (const std::string& t : o.times) times.emplace_back(t, light::parse_utc_time(t));
    } else {
        for (double h : o.solar_hours) times.emplace_back(label_of(h), solar_time(o.date, h, centre.x));
    }
    for (const auto& [label, when] : times) {
        light::SunPositionInput spi;
        spi.time = when;
        spi.observer = {centre.y, centre.x, std::isnan(centre_z) ? 0.0 : double(centre_z)};
        spi.atmosphere = light::Atmosphere::standard_at(spi.observer.height_m);
        const light::SunPosition sp = light::sun_position(spi);
        out.push_back({label, light::format_utc_time(when), {sp.azimuth_deg, sp.elevation_deg}});
    }
    return out;
}

// The reference of one sun on the sampled texels and over every texel's sun mask.
struct SunReference {
    std::unique_ptr<light::Sky> sky;
    std::vector<render::ReferenceSample> samples;
    std::vector<float> sun_visibility;
    double seconds = 0, sun_ms = 0;
};

void run_window(const BenchRenderOptions& o, const std::string& name, const dem::Dem& dem, int col0, int row0,
                std::vector<Row>& rows) {
    const visibility::VisibilityGrid vgrid(dem);
    const terrain::HeightGrid& grid = vgrid.view();
    const double roughness = quality::mean_tan_slope(grid);
    render::NormalField normals = render::terrain_normals(grid, o.threads);
    render::MaterialRaster materials = render::rule_materials(grid, normals);
    const render::ViewDirections view;  // map: looking straight down

    const std::vector<std::size_t> texels = sample_texels(grid, o.samples, o.seed);
    render::ReferenceOptions refo;
    refo.azimuths = o.azimuths;
    refo.curvature = !o.no_curvature;
    refo.threads = o.threads;
    Stopwatch t0;
    // The renderer's own normals (water flattened) and materials: only lighting differs. Normals
    // and materials do not depend on the renderer's knobs, so the reference is built once.
    const render::ReferenceShader reference(grid, materials, normals, view, texels, refo);
    const double horizons_s = t0.milliseconds() / 1000.0;

    const std::vector<StudySun> suns = study_suns(o, dem);
    // The sky the default renderer takes (its aureole stays in the sky over the horizons); the
    // log-SH rows, which light through SH, are measured under the same sky.
    const light::SkyOptions sky_options = render::sky_for(light::parse_sky_options(o.sky), render::SkyLightSettings{});
    std::vector<SunReference> refs;
    for (const StudySun& s : suns) {
        SunReference r;
        r.sky = light::make_sky(sky_options, render::sun_direction(s.sun));
        t0.restart();
        r.samples = reference.render(*r.sky, s.sun);
        r.seconds = t0.seconds() + horizons_s / double(suns.size());
        t0.restart();
        r.sun_visibility = render::reference_sun_visibility(grid, s.sun.azimuth_deg, s.sun.elevation_deg,
                                                            r.sky->sun().angular_radius_rad, !o.no_curvature, o.threads);
        r.sun_ms = t0.milliseconds();
        refs.push_back(std::move(r));
    }

    std::vector<glm::vec3> frame;
    for (int directions : o.directions)
        for (const std::string& sun_shadows : o.sun_shadows)
            for (const std::string& transfer : o.terrain_transfers) {
                render::RendererOptions ro;
                // The reference is direct light (reference_shading.hpp): no bounce on either side.
                ro.bounce.bounces = 0;
                ro.terrain_transfer = transfer == "log-sh" ? render::RendererOptions::TerrainTransfer::log_sh
                                                           : render::RendererOptions::TerrainTransfer::exact;
                ro.directions = directions;
                ro.curvature = !o.no_curvature;
                ro.threads = o.threads;
                ro.sun_method = visibility::parse_sun_method(sun_shadows);
                const std::unique_ptr<render::ShadingState> state =
                    render::compute_shading_state(grid, materials, normals, ro);
                const render::ViewShading view_shading = render::compute_view_shading(*state, view);
                render::FrameRenderer renderer(*state, view_shading);
                std::printf(
                    "%s at %d,%d: %dx%d, mean tan slope %.3f, D %d, sun %s, terrain transfer %s: visibility %.2f s, "
                    "transfer %.2f s\n",
                    name.c_str(), col0, row0, grid.width, grid.height, roughness, directions, sun_shadows.c_str(),
                    transfer.c_str(), state->visibility_seconds(), state->transfer_seconds());
                for (std::size_t si = 0; si < suns.size(); ++si) {
                    const render::SunState& sun = suns[si].sun;
                    const SunReference& ref = refs[si];
                    Row row;
                    row.dem = name;
                    row.label = suns[si].label;
                    row.time = suns[si].time;
                    row.col0 = col0, row.row0 = row0;
                    row.width = grid.width;
                    row.height = grid.height;
                    row.directions = directions;
                    row.sun_shadows = sun_shadows;
                    row.terrain_transfer = transfer;
                    row.mean_tan_slope = roughness;
                    row.state_s = state->visibility_seconds() + state->transfer_seconds();
                    row.azimuth_deg = sun.azimuth_deg;
                    row.elevation_deg = sun.elevation_deg;

                    t0.restart();
                    renderer.render(*ref.sky, sun, frame);
                    row.frame_ms = t0.milliseconds();
                    row.sun_visibility_ms = renderer.last_timings().sun_visibility_s * 1000.0;
                    row.reference_s = ref.seconds;
                    row.reference_sun_ms = ref.sun_ms;

                    std::vector<double> got, want, got_lit, want_lit, got_shadow, want_shadow;
                    for (std::size_t k = 0; k < texels.size(); ++k) {
                        const double a = luminance(frame[texels[k]]), b = luminance(ref.samples[k].radiance);
                        if (!std::isfinite(a) || !std::isfinite(b)) continue;
                        got.push_back(a), want.push_back(b);
                        const bool lit = ref.samples[k].sun_fraction >= 0.5f;
                        (lit ? got_lit : got_shadow).push_back(a);
                        (lit ? want_lit : want_shadow).push_back(b);
                    }
                    row.samples = int(got.size());
                    const bench::RelativeErrors all = bench::relative_errors(got, want);
                    row.rel_rmse = all.rmse, row.rel_p99 = all.p99, row.rel_bias = all.bias;
                    row.sun_lit_rel_rmse = bench::relative_errors(got_lit, want_lit).rmse;
                    row.shadow_rel_rmse = bench::relative_errors(got_shadow, want_shadow).rmse;

                    // Shadow masks over every texel.
                    const light::SunDisc disc = ref.sky->sun();
                    const std::vector<float>& ren_sun = renderer.sun_visibility();
                    const bool sun_up = (disc.irradiance.x > 0 || disc.irradiance.y > 0 || disc.irradiance.z > 0) &&
                                        sun.elevation_deg > -disc.angular_radius_rad * 180.0 / kPi;
                    bench::MaskAgreement masks;
                    for (std::size_t i = 0; i < ref.sun_visibility.size(); ++i) {
                        if (std::isnan(ref.sun_visibility[i]) || std::isnan(ren_sun[i])) continue;
                        masks.add(sun_up ? ref.sun_visibility[i] : 0.0f,
                                  ren_sun[i]);  // sun below the horizon: all shadow
                    }
                    row.iou = masks.iou();
                    row.mask_disagree = masks.disagreement();
                    row.sun_fraction_mae = masks.mean_abs_difference();
                    row.shadow_share = masks.reference_shadow_share();
                    rows.push_back(row);
                    print_row(row);
                }
            }
}

void run_dem(const BenchRenderOptions& o, const std::string& path, std::vector<Row>& rows) {
    DemInput in;
    in.files = {path};
    const dem::Dem dem = load_dem_input(in);
    const std::string name = std::filesystem::path(path).filename().string();
    if (o.window <= 0) return run_window(o, name, dem, 0, 0, rows);
    for (const std::string& at : o.window_at) {
        double fx = 0, fy = 0;
        if (std::sscanf(at.c_str(), "%lf:%lf", &fx, &fy) != 2 || !(fx >= 0 && fx <= 1 && fy >= 0 && fy <= 1))
            throw InputError("--window-at " + at + ": give FX:FY, fractions 0..1 of the DEM's width and height");
        const int w = std::min(o.window, dem.width), h = std::min(o.window, dem.height);
        const int c0 = int(std::lround(fx * (dem.width - w))), r0 = int(std::lround(fy * (dem.height - h)));
        run_window(o, name, dem::texel_window(dem, c0, r0, w, h), c0, r0, rows);
    }
}

void run_bench_render(const BenchRenderOptions& o) {
    if (o.dems.empty()) throw InputError("bench render: give at least one DEM");
    IoPlan plan;
    plan.inputs("DEM", o.dems).input("--sky", light::parse_sky_options(o.sky).hdr_path).output("--csv", o.csv, {".csv"});
    plan.check();
    std::printf("%-34s %-8s %7s %6s %6s %9s %9s %9s %8s %9s %8s %8s %8s %7s\n", "dem", "sun", "az", "el", "n",
                "rel_rmse", "rel_p99", "rel_bias", "iou", "mask_diff", "frame_ms", "sunvis", "ref_sun", "ref_s");
    std::vector<Row> rows;
    for (const std::string& d : o.dems) run_dem(o, d, rows);
    if (!o.csv.empty())
        write_atomically(o.csv, [&](const std::filesystem::path& tmp) {
            std::ofstream out(tmp, std::ios::binary);
            out << csv_text(rows);
            if (!out.flush()) throw input_error(o.csv, "cannot write");
        });
    if (!o.csv.empty()) std::printf("wrote %s\n", o.csv.c_str());
}

}  // namespace

void add_bench_render_command(CLI::App& bench) {
    auto o = std::make_shared<BenchRenderOptions>();
    CLI::App* cmd = bench.add_subcommand(
        "render", "Map radiance and sun shadows of the renderer against the ray-traced reference (docs/accuracy.md)");
    cmd->add_option("DEM", o->dems, "DEM files, each measured on its own")->required();
    cmd->add_option("--times", o->times,
                    "ISO 8601 UTC times (default: local mean solar 08:30, 12:00 and 16:30 of --date at each DEM's "
                    "centre)")
        ->delimiter(',');
    cmd->add_option("--date", o->date, "Date of the default morning/noon/evening (YYYY-MM-DD)")->capture_default_str();
    cmd->add_option("--samples", o->samples, "Texels shaded by the reference per DEM (random, fixed seed)")
        ->capture_default_str()
        ->check(within(1, 10000000));
    cmd->add_option("--seed", o->seed, "Seed of the texel sample")->capture_default_str();
    cmd->add_option("--sky", o->sky, "Sky model (as render --sky)")->capture_default_str();
    cmd->add_option("--directions", o->directions, "Renderer's horizon directions D (a list: one study each)")
        ->capture_default_str()
        ->delimiter(',')
        ->check(within(4, 4096));
    cmd->add_option("--sun-shadows", o->sun_shadows, "Renderer's sun shadows: sweep, exact or both (a list)")
        ->capture_default_str()
        ->delimiter(',')
        ->check(CLI::IsMember({"sweep", "exact"}));
    cmd->add_option("--terrain-transfer", o->terrain_transfers,
                    "Renderer's terrain transfer: exact, log-sh or both (a list; as render --terrain-transfer)")
        ->capture_default_str()
        ->delimiter(',')
        ->check(CLI::IsMember({"exact", "log-sh"}));
    cmd->add_option("--suns", o->suns, "Sun positions AZIMUTH/ELEVATION in degrees, instead of --times")
        ->delimiter(',');
    cmd->add_option("--window", o->window, "Measure square windows of N texels instead of the whole DEM (0: whole)")
        ->capture_default_str()
        ->check(within(0, 100000));
    cmd->add_option("--window-at", o->window_at, "Where the windows lie: FX:FY fractions of the DEM (a list)")
        ->capture_default_str()
        ->delimiter(',');
    cmd->add_option("--reference-azimuths", o->azimuths, "Reference horizon azimuths (>= 720 for the issue's study)")
        ->capture_default_str()
        ->check(within(4, 100000));
    cmd->add_flag("--no-curvature", o->no_curvature, "Flat Earth for both");
    cmd->add_option("--threads", o->threads, "Worker threads (0 = one per core)")->capture_default_str();
    cmd->add_option("--csv", o->csv, "Write the rows as CSV (input of scripts/chart_render.py)");
    cmd->callback([o] {
        if (o->date.size() != 10) throw InputError("--date: expected YYYY-MM-DD, got '" + o->date + "'");
        try {
            (void)light::parse_utc_time(o->date + "T00:00:00Z");
        } catch (const InputError& e) {
            throw InputError(std::string("--date ") + e.what());
        }
        run_bench_render(*o);
    });
}

}  // namespace ts::app
