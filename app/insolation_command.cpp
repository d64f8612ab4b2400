// `terrashade insolation DEM... (--year Y | --from DATE --to DATE) [--by year|month|day] ...`:
// clear-sky solar irradiation (global, beam, diffuse, reflected, kWh/m^2) and hours of direct
// sun per texel over periods, from the exact horizons (core/solar, docs/insolation.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/compute_device.hpp"
#include "app/dem_sun_tables.hpp"
#include "app/dem_input.hpp"
#include "app/insolation_quicklook.hpp"
#include "app/insolation_shards.hpp"
#include "app/shard_option.hpp"
#include "app/io_plan.hpp"
#include "app/job_memory.hpp"
#include "app/options/insolation_options.hpp"
#include "app/options/threads_option.hpp"
#include "core/material/material_sources.hpp"
#include "core/raster/float_cog_writer.hpp"
#include "core/solar/insolation_map.hpp"
#include "core/solar/insolation_model.hpp"
#include "core/solar/shortwave_albedo.hpp"
#include "core/solar/terrain_reflection.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/tiles/block_shading.hpp"
#include "core/tiles/tile_export.hpp"
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
    InsolationArgs sun;
    std::string by = "year";
    double band_step_deg = 0.05, level_step_m = 1000.0;
    int directions = 64, bins_per_direction = 4;
    int threads = 0;
    std::string out, quicklook;
    std::string materials;  // ESA WorldCover GeoTIFF: a shortwave albedo per texel
    std::string shard;  // K/N: rows of the map (insolation_shards.hpp)
    DeviceArgs device;
};

// Everything that changes a value of the map, for the shards' records: shards of two jobs
// never merge.
std::string describe_job(const InsolationOptions& o, const dem::Dem& dem) {
    char grid[160];
    std::snprintf(grid, sizeof grid, "by %s; directions %d x %d; latitude step %.9g level step %.9g", o.by.c_str(),
                  o.directions, o.bins_per_direction, o.band_step_deg, o.level_step_m);
    std::string materials;
    if (!o.materials.empty()) {
        std::error_code ec;
        const auto bytes = std::filesystem::file_size(o.materials, ec);
        materials = "; materials " + std::filesystem::path(o.materials).filename().string() + " " +
                    std::to_string(ec ? 0 : bytes) + " bytes";
    }
    return "dem " + tiles::dem_identity(dem) + "; " + describe_insolation_sum(o.sun) + "; " + grid + materials;
}

constexpr int kMaxBands = 2000;  // --by day over ~a year at most (5 quantities a day)

// Everything a user can get wrong, before the DEM is read.
solar::InsolationSettings check_options(const InsolationOptions& o) {
    const auto [first, last] = insolation_dates(o.sun);
    solar::InsolationSettings s = insolation_settings(o.sun);
    s.periods = solar::make_periods(first, last, solar::parse_period_split(o.by), 0.0);
    if (s.periods.size() * solar::kQuantities > std::size_t(kMaxBands))
        throw InputError("insolation: " + std::to_string(s.periods.size()) + " periods would make " +
                         std::to_string(s.periods.size() * solar::kQuantities) + " bands (at most " +
                         std::to_string(kMaxBands) + "); use a coarser --by or a shorter range");
    s.azimuth_bins = o.directions * o.bins_per_direction;
    s.svf_stride = o.bins_per_direction;
    const int gather = o.sun.reflection.directions;
    if (gather > 0 && o.directions % gather != 0)
        throw InputError("--reflection-directions " + std::to_string(gather) + ": a divisor of --directions (" +
                         std::to_string(o.directions) + "), whose horizons are exact there");
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
    if (!o.materials.empty()) plan.inputs("--materials", {o.materials});
    plan.output("--out", o.out, raster::float_raster_extensions());
    plan.output("--quicklook", o.quicklook, raster::image_extensions([](const raster::ImageFormat& f) {
                    return f.writer == raster::ImageWriter::png;
                }));
    plan.check();
    const Shard shard = shard_of_process(o.shard);
    if (!shard.whole() && !o.quicklook.empty())
        throw InputError("--quicklook: a shard holds a part of the map; give it to the single run, not with --shard");

    const Stopwatch total;
    dem::Dem dem = load_dem_input(o.dem);
    warn_if_single_line(dem);
    raise_sea_floor_to_surface(dem);
    // Each texel's shortwave albedo from the land cover, read before the heavy work.
    std::vector<float> texel_albedo;
    if (!o.materials.empty())
        texel_albedo = solar::shortwave_albedo_of(render::read_landcover_on_grid(o.materials, dem.georef),
                                                  float(settings.albedo));
    // The rows this process sums: all, or its shard's.
    // More shards than rows would leave some with no rows to write, and their merge could never
    // be whole: every shard of such a job refuses, not only the empty ones.
    if (shard.count > dem.height)
        throw InputError("--shard " + shard_text(shard) + ": the DEM has " + std::to_string(dem.height) +
                         " rows, fewer than the " + std::to_string(shard.count) + " shards; use at most " +
                         std::to_string(dem.height));
    const IndexRange part = frame_range(std::size_t(dem.height), shard);
    // The first pass covers the rows the reflection's gather reads too (its radius, the bilinear
    // cell and a rounding row, within the DEM), so that a shard's rows get the single run's values.
    const int reach = o.sun.reflection.enabled() ? int(std::ceil(o.sun.reflection.radius_texels)) + 2 : 0;
    const int row_begin = std::max(0, int(part.begin) - reach);
    const int row_end = std::min(dem.height, int(part.end) + reach);
    const visibility::ReceiverWindow rows{0, row_begin, dem.width, row_end - row_begin};
    const std::uint64_t texels = std::uint64_t(dem.width) * std::uint64_t(rows.height);
    const std::uint64_t kept_rows = part.size(), kept_texels = std::uint64_t(dem.width) * kept_rows;
    const std::uint64_t bands = settings.periods.size() * solar::kQuantities;
    check_job_memory("insolation of " + std::to_string(dem.width) + "x" + std::to_string(rows.height) + " texels",
                     visibility_peak_bytes(texels, o.directions, false) + texels * (bands * 8 + 16) +
                         (o.sun.reflection.enabled() ? texels * settings.periods.size() * 12 : 0),
                     "use --crop, a coarser --by, or fewer --directions");
    const terrain::HeightGrid grid = terrain::metric_view(dem);
    // Horizons.
    const ComputeDevice device(o.device);
    visibility::VisibilityRequest request;
    request.horizon.directions = o.directions;
    request.horizon.threads = o.threads;
    request.horizon.window = rows;  // a shard's receivers, over the whole DEM: one run's horizons
    ProgressBar horizon_bar("horizons", texels * std::uint64_t(o.directions), "rays");
    request.horizon.progress = &horizon_bar;
    const Stopwatch t_vis;
    const visibility::VisibilityResult vis = device.visibility().compute(grid, request);
    horizon_bar.finish();
    const double vis_s = t_vis.seconds();
    if (vis.horizons.texels() != texels) throw std::logic_error("insolation: the horizons do not cover the rows");
    // The rows as a grid of their own, with their normals (from the whole grid, so the shard's
    // edge rows have their neighbours) and latitudes.
    std::vector<float> row_z;
    std::vector<std::uint8_t> row_voids;
    const terrain::HeightGrid row_grid = tiles::window_grid(grid, rows, row_z, row_voids);
    render::NormalField normals = render::terrain_normals(grid, o.threads);
    const std::size_t first_texel = std::size_t(rows.row0) * std::size_t(dem.width);
    for (std::vector<float>* v : {&normals.x, &normals.y, &normals.z})
        *v = std::vector<float>(v->begin() + std::ptrdiff_t(first_texel), v->begin() + std::ptrdiff_t(first_texel + texels));

    // The period's sun: tables per latitude band and elevation level.
    const auto [first, last] = insolation_dates(o.sun);
    const DemSunTables sun = build_dem_sun_tables(dem, settings, first, last, solar::parse_period_split(o.by),
                                                  o.band_step_deg, o.level_step_m);
    settings = sun.settings;
    const solar::InsolationModel& model = *sun.model;
    const double tables_s = sun.seconds;

    const Stopwatch t_sum;
    ProgressBar sum_bar("insolation", texels, "texels");
    const std::span<const float> latitude(sun.latitude.data() + first_texel, texels);
    solar::InsolationMap all_rows = solar::integrate_insolation(model, row_grid, vis.horizons, normals, latitude, &sum_bar);
    sum_bar.finish();
    const double sum_s = t_sum.seconds();
    // Pass 2: the reflected light from the terrain each texel sees.
    const Stopwatch t_reflect;
    const std::span<const float> rows_albedo =
        texel_albedo.empty() ? std::span<const float>() : std::span<const float>(texel_albedo.data() + first_texel, texels);
    solar::apply_terrain_reflection(all_rows, row_grid, vis.horizons, normals, settings.albedo, o.sun.reflection,
                                    o.threads, rows_albedo);
    const double reflect_s = t_reflect.seconds();
    const int kept_row0 = int(part.begin) - rows.row0;
    const solar::InsolationMap map = kept_rows == std::uint64_t(rows.height)
                                         ? std::move(all_rows)
                                         : solar::map_rows(all_rows, kept_row0, int(kept_rows));

    std::vector<std::string> names, units;
    for (const auto& p : settings.periods)
        for (int q = 0; q < solar::kQuantities; ++q) {
            names.push_back(band_name(p, q));
            units.push_back(solar::quantity_unit(q));
        }
    StagedOutputs outputs;
    std::string record;  // a shard says which rows of which job it holds, for `merge`
    if (!shard.whole())
        record = insolation_shard_text({describe_job(o, dem), shard, int(part.begin), int(kept_rows), dem.height, names, units});
    outputs.stage(o.out, [&](const std::filesystem::path& tmp) {
        raster::write_float_cog(tmp, dem.width, int(kept_rows), int(bands), map.values.data(),
                                dem.georef.window(0, int(part.begin), dem.width, int(kept_rows)), names, units, record);
    });
    QuicklookRange range;
    if (!o.quicklook.empty()) {
        // The global irradiation of the whole range (every period summed).
        std::vector<float> global(kept_texels, 0.0f);
        for (int p = 0; p < map.periods; ++p) {
            const float* g = map.band(p, solar::kGlobal);
            for (std::size_t i = 0; i < kept_texels; ++i) global[i] += g[i];
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
    if (!shard.whole())
        std::printf("shard %s: rows %d..%d of %d\n", shard_text(shard).c_str(), int(part.begin), int(part.end) - 1,
                    dem.height);
    const std::string periods = settings.periods.size() == 1
                                    ? "1 period (" + settings.periods.front().label + ")"
                                    : std::to_string(settings.periods.size()) + " periods (" +
                                          settings.periods.front().label + " .. " + settings.periods.back().label + ")";
    std::printf("insolation: %dx%d texels, %s, %d azimuths x %d bins, %d latitude band%s x %d "
                "level%s, %zu sun steps of %.3g min\n",
                dem.width, int(kept_rows), periods.c_str(), o.directions,
                o.bins_per_direction, model.bands(), model.bands() == 1 ? "" : "s", model.levels(),
                model.levels() == 1 ? "" : "s", model.samples(), settings.step_minutes);
    std::printf("  horizons on %s: %.2f s; sun tables: %.2f s (%.1f MB); per-texel sums: %.2f s; reflection's gather: "
                "%.2f s; total %.2f s\n",
                vis.path().c_str(), vis_s, tables_s, double(model.table_bytes()) / 1e6, sum_s, reflect_s,
                total.seconds());
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
        "exact horizons, the CIE clear sky through each texel's horizons, light reflected by the terrain it sees): "
        "global, beam, diffuse, reflected (kWh/m2) and hours of direct sun, one band each per period "
        "(docs/insolation.md)");
    add_dem_input_options(*cmd, o->dem);
    add_insolation_options(*cmd, o->sun);
    cmd->add_option("--by", o->by, "One set of bands per year, month or day of the range")
        ->capture_default_str()
        ->check(CLI::IsMember({"year", "month", "day"}));
    cmd->add_option("--directions", o->directions, "Horizon azimuths D (the sun is looked up in 4 D azimuth bins)")
        ->capture_default_str()
        ->check(within(8, 1024));
    cmd->add_option("--latitude-step", o->band_step_deg,
                    "Spacing of the latitude bands of the sun tables, degrees (each texel takes the nearest)")
        ->capture_default_str()
        ->check(within(0.001, 5.0));
    cmd->add_option("-o,--out", o->out,
                    "Float32 Cloud-Optimized GeoTIFF, bands described with quantity, period and unit")->required();
    cmd->add_option("--quicklook", o->quicklook, "PNG of the global irradiation with a colour ramp and legend");
    cmd->add_option("--materials", o->materials,
                    "A land-cover GeoTIFF of ESA WorldCover class codes, resampled to the DEM by georeferencing: each "
                    "class's shortwave albedo (docs/insolation.md) replaces --albedo where it has one");
    add_shard_option(*cmd, o->shard);
    add_threads_option(*cmd, o->threads);
    add_device_options(*cmd, o->device);
    cmd->callback([o] { run_insolation(*o); });
}

}  // namespace ts::app
