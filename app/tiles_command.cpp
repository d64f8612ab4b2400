// `terrashade tiles`: Web Mercator map tiles of a shaded DEM, as an XYZ directory (DIR/z/x/y.png)
// or one MBTiles file, resumable after a crash (docs/tiles.md). The work is core/tiles; this
// file parses, checks everything it can before the heavy part, and reports.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "app/command.hpp"
#include "app/dem_input.hpp"
#include "app/interrupt_watcher.hpp"
#include "app/io_plan.hpp"
#include "app/shard_option.hpp"
#include "app/tile_set_viewer.hpp"
#include "app/tiles_options.hpp"
#include "core/dem/wrap_longitude.hpp"
#include "core/light/sky.hpp"
#include "core/light/utc_time.hpp"
#include "core/raster/raster_writer.hpp"
#include "core/render/render_scene.hpp"
#include "core/tiles/mbtiles_file.hpp"
#include "core/util/shard_marker.hpp"
#include "core/tiles/tile_export.hpp"
#include "core/tiles/xyz_directory.hpp"
#include "core/util/error.hpp"
#include "core/util/progress_bar.hpp"
#include "core/util/stopwatch.hpp"
#include "core/util/temp_files.hpp"
#include "core/raster/image_writer_registry.hpp"

namespace ts::app {
namespace {

struct TilesCommandArgs {
    DemInput dem;
    TilesArgs tiles;
    std::string out;
    bool resume = false;
    bool overwrite = false;
    std::string name, attribution;
    std::string debug_heights;  // Z/X/Y
    std::string shard;          // K/N
};

// A geographic DEM whose texel centres lie past 180 degrees (a 0..360 grid) would lose that part:
// Web Mercator tiles end at +-180 and the DEM's longitudes are not wrapped. Refused with what to
// do; a global grid's half cell beyond (ETOPO1's -180.5..180.5 edges) is fine.
void refuse_past_the_antimeridian(const dem::Dem& dem) {
    if (!dem.georef.crs().is_geographic()) return;
    const double west = dem.georef.pixel_to_lonlat(0.5, dem.height * 0.5).x;
    const double east = dem.georef.pixel_to_lonlat(dem.width - 0.5, dem.height * 0.5).x;
    if (west >= -180.0 - 1e-9 && east <= 180.0 + 1e-9) return;
    char text[240];
    std::snprintf(text, sizeof text,
                  "spans %.4g..%.4g degrees of longitude, past 180: its tiles would lose that part; shift it into "
                  "-180..180 (gdalwarp -t_srs EPSG:4326 --config CENTER_LONG 0) or split it at 180",
                  west, east);
    throw input_error(dem.source, text);
}

// --debug-heights Z/X/Y, checked before any work: a tile of one of the job's zooms.
std::optional<tiles::TileId> parse_debug_heights(const std::string& zxy, const tiles::TileJob& job) {
    if (zxy.empty()) return std::nullopt;
    tiles::TileId t;
    char rest = 0;
    if (std::sscanf(zxy.c_str(), "%d/%d/%d%c", &t.z, &t.x, &t.y, &rest) != 3)
        throw InputError("--debug-heights " + zxy + ": give Z/X/Y");
    if (t.z < job.z0 || t.z > job.z1)
        throw InputError("--debug-heights " + zxy + ": zoom " + std::to_string(t.z) + " is not one of the job's (" +
                         std::to_string(job.z0) + "-" + std::to_string(job.z1) + ")");
    const long long n = 1LL << t.z;
    if (t.x < 0 || t.y < 0 || t.x >= n || t.y >= n)
        throw InputError("--debug-heights " + zxy + ": zoom " + std::to_string(t.z) + " has tiles 0.." +
                         std::to_string(n - 1) + " in x and y");
    return t;
}

// --debug-heights Z/X/Y: the tile's heights with their halo as a float GeoTIFF in EPSG:3857,
// beside the tiles (the input gdaldem gets in tests/cli/tiles_cli_test.cpp).
void write_debug_heights(const dem::Dem& dem, const tiles::TileJob& job, const tiles::TileId& t,
                         const std::string& out) {
    const tiles::TileHeights h = tiles::tile_heights(dem, job, t);
    const std::filesystem::path dir = raster::written_as(out, raster::ImageWriter::mbtiles) ? std::filesystem::path(out).parent_path()
                                                                : std::filesystem::path(out);
    const std::string name =
        std::to_string(t.z) + "-" + std::to_string(t.x) + "-" + std::to_string(t.y) + "-heights.tif";
    raster::write_float_raster(dir / name, h.georef.width(), h.georef.height(), 1, h.z.data(), h.georef,
                               {"height (m) the tile is shaded from"});
}

void run_tiles(const TilesCommandArgs& a) {
    // Every check that needs no DEM first.
    tiles::TileJob job = tile_job(a.tiles);
    const bool mbtiles = raster::written_as(a.out, raster::ImageWriter::mbtiles);
    if (a.out.empty()) throw InputError("tiles: --out DIR or FILE.mbtiles");
    if (a.resume && a.overwrite) throw InputError("tiles: --resume keeps the tiles, --overwrite replaces them: give one");
    const std::optional<tiles::TileId> debug_tile = parse_debug_heights(a.debug_heights, job);
    IoPlan plan;
    plan.inputs("DEM", a.dem.files);
    plan.input("--sky", job.shading.sky.hdr_path);
    plan_colors_input(plan, a.tiles.colors);
    if (mbtiles) {
        plan.output("--out", a.out, raster::tile_set_extensions());
    } else {
        std::error_code ec;
        if (std::filesystem::exists(a.out, ec) && !std::filesystem::is_directory(a.out, ec))
            throw input_error(a.out, "is a file; --out takes a directory (XYZ tiles) or FILE.mbtiles");
        // `--out t.png` means a picture, not a folder of tiles named t.png: a new folder takes no
        // file extension (an existing folder is taken as it is).
        const std::string ext = std::filesystem::path(a.out).extension().string();
        if (!ext.empty() && !std::filesystem::exists(a.out, ec))
            throw InputError("--out " + a.out + ": tiles go to a folder (no file extension) or a .mbtiles file, not " +
                             ext);
        plan.output_directory("--out", a.out);
    }
    plan.check();
    job.shard = shard_of_process(a.shard);

    dem::Dem dem = load_dem_input(a.dem);
    refuse_past_the_antimeridian(dem);
    if (dem::spans_all_longitudes(dem)) {
        // A global grid goes on across 180 (core/dem/wrap_longitude.hpp): an eighth of the turn
        // (a 1-degree grid's 45 texels; at most 2048, as far as the horizons matter) on each side.
        const int period = int(std::lround(360.0 / dem.georef.transform().dx_col));
        dem = dem::wrap_longitudes(dem, std::min(period / 8, 2048));
    }
    if (job.shading.style->name() == "insolation") raise_sea_floor_to_surface(dem);
    job.dem = tiles::dem_identity(dem);
    job.shading.colors = render::fit_colors(job.shading.colors, dem);
    job.shading.grid_north_deg = dem.georef.grid_azimuth_of_north_deg();
    if (!a.tiles.time.empty()) {
        const render::SunState sun = render::sun_at_dem_centre(dem, light::parse_utc_time(a.tiles.time));
        job.shading.sun_azimuth_deg = sun.azimuth_deg, job.shading.sun_elevation_deg = sun.elevation_deg;
        const std::string_view style = job.shading.style->name();  // the styles lit by the sun
        if (sun.elevation_deg < -0.27 && (style == "relief" || style == "color" || style == "hillshade"))
            std::fprintf(stderr, "terrashade: warning: the sun is below the horizon (elevation %.2f deg): sky light only\n",
                         sun.elevation_deg);
    }
    if (job.shading.style->uses_visibility()) choose_tile_directions(a.tiles, dem, job);
    const std::vector<tiles::TileId> tile_plan = tiles::plan_tiles(dem, job);
    if (a.tiles.verbose) {
        std::printf("sun: azimuth %.2f deg, elevation %.2f deg\n", job.shading.sun_azimuth_deg, job.shading.sun_elevation_deg);
        for (int z = job.z0; z <= job.z1; ++z) {
            const tiles::ZoomShading zs = tiles::zoom_shading(dem, job, z + tiles::tile_size_shift(job.tile_size));
            const double rule = zs.rule_exaggeration * job.shading.z_factor;
            char raised[96] = "";
            if (rule > 0 && zs.vertical_scale > rule * 1.0001)
                std::snprintf(raised, sizeof raised, " (raised from %.3g for legible relief: docs/tiles.md)", rule);
            std::printf("zoom %d: DEM level %d (1 in %d texels a side), heights x %.3g%s, %d directions\n", z, zs.level,
                        1 << zs.level, zs.vertical_scale, raised, tiles::shading_of_zoom(job, z).directions);
        }
        std::fflush(stdout);
    }
    if (tile_plan.empty() && job.shard.whole())
        throw input_error(dem.source, "covers no Web Mercator tile (it lies beyond +-85.05 deg latitude?)");

    // The sky once before the output is touched: an unreadable --sky map fails here, not after an
    // old tile set was replaced.
    if (job.shading.style->uses_visibility() && job.shading.sky.kind == light::SkyOptions::Kind::hdr)
        light::make_sky(job.shading.sky, render::sun_direction({job.shading.sun_azimuth_deg, job.shading.sun_elevation_deg}));

    // The output, before any shading: an unwritable one fails here.
    const std::string job_text = tiles::describe_job(job);
    const tiles::TileSetInfo info =
        tile_set_info(a.name, a.attribution, a.dem.files, dem, job, tile_set_legend(a.tiles, job));
    if (a.attribution.empty() && dem.credit.empty())
        std::fprintf(stderr,
                     "terrashade: note: the DEM does not say who made it, so the maps credit its file name; "
                     "credit its source with --attribution (e.g. 'elevation data: NOAA ETOPO1')\n");
    // A lightable set's sky tables and site, for the reader that relights it.
    const std::string lightable = job.shading.style->data_tile() ? tiles::lightable_json(dem, job.shading) : "";
    std::unique_ptr<tiles::TileSink> sink;
    if (mbtiles) {
        std::map<std::string, std::string> metadata = tiles::mbtiles_metadata(info);
        if (!lightable.empty()) metadata["terrashade_lightable"] = lightable;
        if (!job.shard.whole()) metadata["terrashade_shard"] = shard_text(job.shard);
        using E = tiles::MbtilesFile::Existing;
        sink = std::make_unique<tiles::MbtilesFile>(a.out, std::move(metadata), job_text,
                                                    a.resume ? E::resume : a.overwrite ? E::overwrite : E::refuse);
        // An interrupt keeps the committed tiles (FILE.partial and its -wal log) for --resume;
        // the -shm index is rebuilt by the next open, so it goes.
        const std::string partial = tiles::MbtilesFile::partial_path(a.out).string();
        temp_files::track(partial + "-shm");
        interrupt::report_kept("the tiles made so far are kept in " + partial + " (and its -wal) for --resume; " +
                               "delete them to drop them");
    } else {
        using E = tiles::XyzDirectory::Existing;
        // A folder made here is known to the interrupt before it exists: one before the first
        // tile removes it (with its job file) instead of leaving it behind.
        std::error_code ec;
        if (!std::filesystem::exists(a.out, ec)) temp_files::track_created_directory(a.out, tiles::XyzDirectory::kJobFile);
        sink = std::make_unique<tiles::XyzDirectory>(a.out, job_text,
                                                     a.resume ? E::resume : a.overwrite ? E::overwrite : E::refuse,
                                                     job.z0, job.z1);
        remove_shard_marker(a.out);
        interrupt::report_kept("any tiles written stay in " + a.out + " for --resume");
    }

    set_tile_insolation(a.tiles, dem, job);  // after the output: a conflicting job is refused first
    const Stopwatch watch;
    tiles::TileExportStats stats;
    {
        ProgressBar bar("tiles", tile_plan.size(), "tiles");
        stats = tiles::export_tiles(dem, job, *sink, &bar);
        bar.finish();
    }
    if (!mbtiles && !job.shard.whole()) write_shard_marker(a.out, job.shard);
    // The viewer last: it appears with a finished tile set (each shard's is the merged set's).
    if (!mbtiles) write_tile_viewer(a.out, info, tile_set_legend(a.tiles, job), lightable);
    const double total = watch.seconds();
    const std::size_t made = stats.written + stats.empty;
    std::printf("tiles: %zu written, %zu resumed, %zu without data (zoom %d-%d, %d px, %s)\n", stats.written,
                stats.resumed, stats.empty, job.z0, job.z1, job.tile_size,
                std::string(job.shading.style->name()).c_str());
    std::printf("time: %.3f s (shading %.3f s, tiles %.3f s: %.0f tiles/s)\n", total, stats.source_seconds,
                stats.tile_seconds, stats.tile_seconds > 0 ? made / stats.tile_seconds : 0.0);
    // --max-error: what each level shaded in blocks chose per block.
    for (const auto& [level, by_d] : stats.blocks_by_directions) {
        int blocks = 0;
        for (const auto& [d, n] : by_d) blocks += n;
        if (job.shading.max_error <= 0 || blocks < 2) continue;
        std::string parts;
        for (const auto& [d, n] : by_d) parts += (parts.empty() ? "" : ", ") + std::to_string(n) + " at " + std::to_string(d);
        std::printf("--max-error: level %d in %d blocks, directions from each block's roughness: %s\n", level, blocks,
                    parts.c_str());
    }
    std::printf("wrote %s\n", a.out.c_str());
    if (debug_tile) write_debug_heights(dem, job, *debug_tile, a.out);
}

}  // namespace

void add_tiles_command(CLI::App& root) {
    auto a = std::make_shared<TilesCommandArgs>();
    CLI::App* cmd = root.add_subcommand(
        "tiles",
        "Web Mercator map tiles of a shaded DEM: an XYZ directory DIR/z/x/y.png or one MBTiles file, with "
        "seamless edges and crash-safe --resume (docs/tiles.md). Without --time or --sun-azimuth/--sun-elevation "
        "the shaded styles take the cartographers' light: azimuth 315, 45 degrees up.");
    add_dem_input_options(*cmd, a->dem);
    add_tiles_options(*cmd, a->tiles);
    cmd->add_option("-o,--out", a->out, "Output: a directory (XYZ tiles DIR/z/x/y.png) or FILE.mbtiles")->required();
    cmd->add_flag("--resume", a->resume,
                  "Continue an interrupted run with the same options: finished tiles are kept, the rest made");
    cmd->add_flag("--overwrite", a->overwrite,
                  "Replace the tiles of another job in --out (only those: other files in the folder stay)");
    add_shard_option(*cmd, a->shard);
    cmd->add_option("--name", a->name,
                    "The tile set's name in its MBTiles metadata, or its tiles.json and viewer page (default: the DEM "
                    "file's name and the style)");
    cmd->add_option("--attribution", a->attribution,
                    "Who made the data, shown on maps of the tiles (MBTiles metadata, tiles.json, the viewer; may hold "
                    "HTML links; default: 'elevation data: ' and the source the DEM files record (GeoTIFF copyright, "
                    "Copernicus or SRTM metadata), else their names, with a note)");
    cmd->add_option("--debug-heights", a->debug_heights,
                    "Also write the heights tile Z/X/Y is shaded from (1-px halo) as Z-X-Y-heights.tif beside the "
                    "tiles, for checking against gdaldem");
    cmd->callback([a] { run_tiles(*a); });
}

}  // namespace ts::app
