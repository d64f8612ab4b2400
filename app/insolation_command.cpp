// `terrashade insolation DEM... (--year Y | --from DATE --to DATE) [--by year|month|day] ...`:
// clear-sky solar irradiation (global, beam, diffuse, reflected, kWh/m^2) and hours of direct
// sun per texel over periods, from the exact horizons (core/solar, docs/insolation.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/compute_device.hpp"
#include "app/dem_input.hpp"
#include "app/insolation_quicklook.hpp"
#include "app/io_plan.hpp"
#include "app/job_memory.hpp"
#include "app/options/threads_option.hpp"
#include "core/raster/float_cog_writer.hpp"
#include "core/solar/insolation_map.hpp"
#include "core/solar/insolation_model.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/util/error.hpp"
#include "core/util/progress_bar.hpp"
#include "core/util/staged_outputs.hpp"
#include "core/util/stopwatch.hpp"
#include "core/visibility/visibility_backend.hpp"
#include "core/raster/image_writer_registry.hpp"
#include "app/options/within_range.hpp"

namespace ts::app {
namespace {

struct InsolationOptions {
    DemInput dem;
    int year = 0;  // 0: not given
    std::string from, to, by = "year";
    double linke = 3.0;
    std::vector<double> linke_monthly;
    double albedo = 0.2, clear_sky_index = 1.0, step_minutes = 2.0;
    double band_step_deg = 0.05, level_step_m = 1000.0;
    int directions = 64, bins_per_direction = 4;
    int threads = 0;
    std::string out, quicklook;
    DeviceArgs device;
};

constexpr int kMaxBands = 2000;  // --by day over ~a year at most (5 quantities a day)

// Everything a user can get wrong, before the DEM is read.
solar::InsolationSettings check_options(const InsolationOptions& o) {
    solar::CalendarDate first, last;
    if (o.year != 0) {
        if (!o.from.empty() || !o.to.empty()) throw InputError("--year: give either --year or --from/--to, not both");
        if (o.year < 1 || o.year > 5999) throw InputError("--year " + std::to_string(o.year) + ": must be in 1..5999");
        first = {o.year, 1, 1}, last = {o.year, 12, 31};
    } else {
        if (o.from.empty() || o.to.empty()) throw InputError("insolation: give --year Y, or --from DATE and --to DATE");
        first = solar::parse_calendar_date(o.from, "--from");
        last = solar::parse_calendar_date(o.to, "--to");
        if (first.year > 5999 || last.year > 5999) throw InputError("--from/--to: years must be in 1..5999");
    }
    solar::InsolationSettings s;
    s.periods = solar::make_periods(first, last, solar::parse_period_split(o.by), 0.0);
    if (s.periods.size() * solar::kQuantities > std::size_t(kMaxBands))
        throw InputError("insolation: " + std::to_string(s.periods.size()) + " periods would make " +
                         std::to_string(s.periods.size() * solar::kQuantities) + " bands (at most " +
                         std::to_string(kMaxBands) + "); use a coarser --by or a shorter range");
    if (!o.linke_monthly.empty()) {
        if (o.linke_monthly.size() != 12)
            throw InputError("--linke-monthly: needs 12 values (January..December), got " +
                             std::to_string(o.linke_monthly.size()));
        std::copy(o.linke_monthly.begin(), o.linke_monthly.end(), s.linke_monthly.begin());
    } else {
        s.linke_monthly.fill(o.linke);
    }
    for (double tl : s.linke_monthly)
        if (!(tl > 0) || tl > 10) throw InputError("Linke turbidity " + std::to_string(tl) + ": must be in (0, 10]");
    s.albedo = o.albedo;
    s.clear_sky_index = o.clear_sky_index;
    s.step_minutes = o.step_minutes;
    s.azimuth_bins = o.directions * o.bins_per_direction;
    s.svf_stride = o.bins_per_direction;
    s.threads = o.threads;
    solar::check_settings(s);
    return s;
}

std::string band_name(const solar::InsolationPeriod& p, int q) {
    const char* what[] = {"global irradiation", "beam irradiation", "diffuse irradiation", "reflected irradiation",
                          "hours of direct sun"};
    return std::string(what[q]) + " " + p.label + " (" + solar::quantity_unit(q) + ")";
}

void run_insolation(InsolationOptions& o) {
    solar::InsolationSettings settings = check_options(o);
    IoPlan plan;
    plan.inputs("DEM", o.dem.files);
    plan.output("--out", o.out, raster::float_raster_extensions());
    plan.output("--quicklook", o.quicklook, raster::image_extensions([](const raster::ImageFormat& f) {
                    return f.writer == raster::ImageWriter::png;
                }));
    plan.check();

    const Stopwatch total;
    const dem::Dem dem = load_dem_input(o.dem);
    warn_if_single_line(dem);
    const std::uint64_t texels = std::uint64_t(dem.width) * dem.height;
    const std::uint64_t bands = settings.periods.size() * solar::kQuantities;
    check_job_memory("insolation of " + std::to_string(dem.width) + "x" + std::to_string(dem.height) + " texels",
                     visibility_peak_bytes(texels, o.directions, false) + texels * (bands * 8 + 16),
                     "use --crop, a coarser --by, or fewer --directions");
    const terrain::HeightGrid grid = terrain::metric_view(dem);
    // The clock of days and months: mean solar time at the DEM's centre.
    const glm::dvec2 centre = dem.georef.pixel_to_lonlat(dem.width * 0.5, dem.height * 0.5);
    if (!std::isfinite(centre.x) || !std::isfinite(centre.y))
        throw InputError(dem.source + ": its CRS gives no longitude and latitude");
    settings.clock_longitude_deg = centre.x;
    const solar::CalendarDate first =
        o.year ? solar::CalendarDate{o.year, 1, 1} : solar::parse_calendar_date(o.from, "--from");
    const solar::CalendarDate last =
        o.year ? solar::CalendarDate{o.year, 12, 31} : solar::parse_calendar_date(o.to, "--to");
    settings.periods = solar::make_periods(first, last, solar::parse_period_split(o.by), centre.x);
    const std::vector<float> latitude = solar::texel_latitudes(dem.georef, o.threads);
    float lat_min = 90, lat_max = -90, z_min = 1e30f, z_max = -1e30f;
    for (std::size_t i = 0; i < latitude.size(); ++i) {
        lat_min = std::min(lat_min, latitude[i]), lat_max = std::max(lat_max, latitude[i]);
        if (std::isfinite(dem.z[i])) z_min = std::min(z_min, dem.z[i]), z_max = std::max(z_max, dem.z[i]);
    }
    if (!(z_max >= z_min)) z_min = z_max = 0;

    // Horizons.
    const ComputeDevice device(o.device);
    visibility::VisibilityRequest request;
    request.horizon.directions = o.directions;
    request.horizon.threads = o.threads;
    ProgressBar horizon_bar("horizons", texels * std::uint64_t(o.directions), "rays");
    request.horizon.progress = &horizon_bar;
    const Stopwatch t_vis;
    const visibility::VisibilityResult vis = device.visibility().compute(grid, request);
    horizon_bar.finish();
    const double vis_s = t_vis.seconds();
    const render::NormalField normals = render::terrain_normals(grid, o.threads);

    // The period's sun: tables per latitude band and elevation level.
    const Stopwatch t_tables;
    // The tables hold a few MB per latitude band and elevation level (a year: ~2.5 MB at 256
    // bins); a DEM spanning many degrees or kilometres gets coarser bands and levels, said.
    constexpr int kMaxLevels = 8, kMaxTableGroups = 160;
    double level_step = o.level_step_m, band_step = o.band_step_deg;
    if ((z_max - z_min) / level_step > kMaxLevels - 1) level_step = (z_max - z_min) / (kMaxLevels - 1);
    const int n_levels = (z_max - z_min) > 1e-9 ? int(std::ceil((z_max - z_min) / level_step - 1e-9)) + 1 : 1;
    const int max_bands = std::max(1, kMaxTableGroups / n_levels);
    if ((lat_max - lat_min) / band_step > max_bands - 1) {
        band_step = (lat_max - lat_min) / (max_bands - 1);
        settings.interpolate_bands = true;
        std::fprintf(stderr,
                     "terrashade: note: the DEM spans %.3g degrees of latitude: sun tables every %.3g degrees (%d bands, "
                     "each texel linear between two) and %d elevation levels, to keep them in memory\n",
                     double(lat_max - lat_min), band_step, max_bands, n_levels);
    }
    const int n_bands = int(std::ceil((lat_max - lat_min) / band_step - 1e-9)) + 1;
    ProgressBar table_bar("sun tables", std::uint64_t(std::max(1, n_bands)), "latitude bands");
    const solar::InsolationModel model(settings, lat_min, lat_max, band_step, z_min, z_max, level_step, &table_bar);
    table_bar.finish();
    const double tables_s = t_tables.seconds();

    const Stopwatch t_sum;
    ProgressBar sum_bar("insolation", texels, "texels");
    const solar::InsolationMap map = solar::integrate_insolation(model, grid, vis.horizons, normals, latitude, &sum_bar);
    sum_bar.finish();
    const double sum_s = t_sum.seconds();

    std::vector<std::string> names, units;
    for (const auto& p : settings.periods)
        for (int q = 0; q < solar::kQuantities; ++q) {
            names.push_back(band_name(p, q));
            units.push_back(solar::quantity_unit(q));
        }
    StagedOutputs outputs;
    outputs.stage(o.out, [&](const std::filesystem::path& tmp) {
        raster::write_float_cog(tmp, dem.width, dem.height, int(bands), map.values.data(), dem.georef, names, units);
    });
    QuicklookRange range;
    if (!o.quicklook.empty()) {
        // The global irradiation of the whole range (every period summed).
        std::vector<float> global(texels, 0.0f);
        for (int p = 0; p < map.periods; ++p) {
            const float* g = map.band(p, solar::kGlobal);
            for (std::size_t i = 0; i < texels; ++i) global[i] += g[i];
        }
        const std::string label = settings.periods.size() == 1
                                      ? settings.periods[0].label
                                      : settings.periods.front().label + ".." + settings.periods.back().label;
        outputs.stage(o.quicklook, [&](const std::filesystem::path& tmp) {
            range = write_insolation_quicklook(tmp.string(), dem.width, dem.height, global.data(),
                                               "global irradiation " + label, "kWh/m2");
        });
    }
    outputs.commit();
    std::printf("insolation: %dx%d texels, %zu period%s (%s .. %s), %d azimuths x %d bins, %d latitude band%s x %d "
                "level%s, %zu sun steps of %.3g min\n",
                dem.width, dem.height, settings.periods.size(), settings.periods.size() == 1 ? "" : "s",
                settings.periods.front().label.c_str(), settings.periods.back().label.c_str(), o.directions,
                o.bins_per_direction, model.bands(), model.bands() == 1 ? "" : "s", model.levels(),
                model.levels() == 1 ? "" : "s", model.samples(), settings.step_minutes);
    std::printf("  horizons on %s: %.2f s; sun tables: %.2f s (%.1f MB); per-texel sums: %.2f s; total %.2f s\n",
                vis.path().c_str(), vis_s, tables_s, double(model.table_bytes()) / 1e6, sum_s, total.seconds());
    std::printf("wrote %s (%llu bands: global, beam, diffuse, reflected in kWh/m2 and hours of direct sun per period)\n",
                o.out.c_str(), (unsigned long long)bands);
    if (!o.quicklook.empty())
        std::printf("wrote %s (global irradiation, colour ramp %.4g..%.4g kWh/m2: the 1st to 99th percentile)\n",
                    o.quicklook.c_str(), double(range.lo), double(range.hi));
}

}  // namespace

void add_insolation_command(CLI::App& root) {
    auto o = std::make_shared<InsolationOptions>();
    CLI::App* cmd = root.add_subcommand(
        "insolation",
        "Clear-sky solar irradiation per texel over a year or dates (ESRA model as r.sun; beam and sun from the "
        "exact horizons, diffuse through each texel's sky view): global, beam, diffuse, reflected (kWh/m2) and "
        "hours of direct sun, one band each per period (docs/insolation.md)");
    add_dem_input_options(*cmd, o->dem);
    cmd->add_option("--year", o->year, "Sum over this calendar year (local mean solar time at the DEM's centre)");
    cmd->add_option("--from", o->from, "First day, YYYY-MM-DD (with --to)");
    cmd->add_option("--to", o->to, "Last day, YYYY-MM-DD, included");
    cmd->add_option("--by", o->by, "One set of bands per year, month or day of the range")
        ->capture_default_str()
        ->check(CLI::IsMember({"year", "month", "day"}));
    cmd->add_option("--linke", o->linke, "Linke turbidity of the whole range (r.sun's linke_value)")
        ->capture_default_str();
    cmd->add_option("--linke-monthly", o->linke_monthly, "Linke turbidity per month, 12 values January..December")
        ->delimiter(',')
        ->type_name("L1,...,L12");
    cmd->add_option("--albedo", o->albedo, "Ground albedo for the reflected irradiation, [0, 1]")->capture_default_str();
    cmd->add_option("--clear-sky-index", o->clear_sky_index,
                    "Real-sky / clear-sky ratio applied to beam and diffuse (1 = clear sky)")
        ->capture_default_str();
    cmd->add_option("--step", o->step_minutes, "Time step of the sun's path in minutes (costs only in the tables)")
        ->capture_default_str();
    cmd->add_option("--directions", o->directions, "Horizon azimuths D (the sun is looked up in 4 D azimuth bins)")
        ->capture_default_str()
        ->check(within(8, 1024));
    cmd->add_option("--latitude-step", o->band_step_deg,
                    "Spacing of the latitude bands of the sun tables, degrees (each texel takes the nearest)")
        ->capture_default_str()
        ->check(within(0.001, 5.0));
    cmd->add_option("--out", o->out,
                    "Float32 Cloud-Optimized GeoTIFF, bands described with quantity, period and unit")->required();
    cmd->add_option("--quicklook", o->quicklook, "PNG of the global irradiation with a colour ramp and legend");
    add_threads_option(*cmd, o->threads);
    add_device_options(*cmd, o->device);
    cmd->callback([o] { run_insolation(*o); });
}

}  // namespace ts::app
