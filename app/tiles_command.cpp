// `terrashade tiles`: Web Mercator map tiles of a shaded DEM, as an XYZ directory (DIR/z/x/y.png)
// or one MBTiles file, resumable after a crash (docs/tiles.md). The work is core/tiles; this
// file parses, checks everything it can before the heavy part, and reports.
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "app/command.hpp"
#include "app/dem_input.hpp"
#include "app/io_plan.hpp"
#include "app/shard_option.hpp"
#include "app/tiles_options.hpp"
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

namespace ts::app {
namespace {

struct TilesCommandArgs {
    DemInput dem;
    TilesArgs tiles;
    std::string out;
    bool resume = false;
    std::string name, attribution;
    std::string debug_heights;  // Z/X/Y
    std::string shard;          // K/N
};

// --debug-heights Z/X/Y: the tile's heights with their halo as a float GeoTIFF in EPSG:3857,
// beside the tiles (the input gdaldem gets in tests/cli/tiles_cli_test.cpp).
void write_debug_heights(const dem::Dem& dem, const tiles::TileJob& job, const std::string& zxy,
                         const std::string& out) {
    tiles::TileId t;
    if (std::sscanf(zxy.c_str(), "%d/%d/%d", &t.z, &t.x, &t.y) != 3)
        throw InputError("--debug-heights " + zxy + ": give Z/X/Y");
    const tiles::TileHeights h = tiles::tile_heights(dem, job, t);
    const std::filesystem::path dir = out.ends_with(".mbtiles") ? std::filesystem::path(out).parent_path()
                                                                : std::filesystem::path(out);
    const std::string name =
        std::to_string(t.z) + "-" + std::to_string(t.x) + "-" + std::to_string(t.y) + "-heights.tif";
    raster::write_float_raster(dir / name, h.georef.width(), h.georef.height(), 1, h.z.data(), h.georef,
                               {"height (m) the tile is shaded from"});
}

void run_tiles(const TilesCommandArgs& a) {
    // Every check that needs no DEM first.
    tiles::TileJob job = tile_job(a.tiles);
    const bool mbtiles = a.out.ends_with(".mbtiles");
    if (a.out.empty()) throw InputError("tiles: --out DIR or FILE.mbtiles");
    IoPlan plan;
    plan.inputs("DEM", a.dem.files);
    if (mbtiles) {
        plan.output("--out", a.out, {".mbtiles"});
    } else {
        std::error_code ec;
        if (std::filesystem::exists(a.out, ec) && !std::filesystem::is_directory(a.out, ec))
            throw input_error(a.out, "is a file; --out takes a directory (XYZ tiles) or FILE.mbtiles");
        plan.output_directory("--out", a.out);
    }
    plan.check();
    job.shard = shard_of_process(a.shard);

    const dem::Dem dem = load_dem_input(a.dem);
    if (!a.tiles.time.empty()) {
        const render::SunState sun = render::sun_at_dem_centre(dem, light::parse_utc_time(a.tiles.time));
        job.shading.sun_azimuth_deg = sun.azimuth_deg, job.shading.sun_elevation_deg = sun.elevation_deg;
    }
    if (tiles::uses_visibility(job.shading.style)) choose_tile_directions(a.tiles, dem, job);
    const std::vector<tiles::TileId> tile_plan = tiles::plan_tiles(dem, job);
    if (tile_plan.empty() && job.shard.whole())
        throw input_error(dem.source, "covers no Web Mercator tile (it lies beyond +-85.05 deg latitude?)");

    // The output, before any shading: an unwritable one fails here.
    const std::string job_text = tiles::describe_job(job);
    std::unique_ptr<tiles::TileSink> sink;
    if (mbtiles) {
        const tiles::LonLatBox box = tiles::dem_footprint(dem.georef);
        char bounds[128], center[128];
        std::snprintf(bounds, sizeof bounds, "%.7f,%.7f,%.7f,%.7f", box.west, box.south, box.east, box.north);
        std::snprintf(center, sizeof center, "%.7f,%.7f,%d", 0.5 * (box.west + box.east), 0.5 * (box.south + box.north),
                      (job.z0 + job.z1) / 2);
        const std::string stem = std::filesystem::path(a.dem.files.front()).stem().string();
        std::map<std::string, std::string> metadata = {
            {"name", a.name.empty() ? stem + " " + std::string(tiles::tile_style_name(job.shading.style)) : a.name},
            {"format", "png"},
            {"bounds", bounds},
            {"center", center},
            {"minzoom", std::to_string(job.z0)},
            {"maxzoom", std::to_string(job.z1)},
            {"attribution", a.attribution.empty() ? "terrashade; elevation: " + stem : a.attribution},
            {"type", "baselayer"},
            {"version", "1"},
            {"description", "terrashade " + std::string(tiles::tile_style_name(job.shading.style)) + ", " +
                                std::to_string(job.tile_size) + "-px tiles"},
        };
        if (!job.shard.whole()) metadata["terrashade_shard"] = shard_text(job.shard);
        sink = std::make_unique<tiles::MbtilesFile>(a.out, std::move(metadata), job_text, a.resume);
    } else {
        sink = std::make_unique<tiles::XyzDirectory>(a.out, job_text, a.resume, job.z0, job.z1);
        remove_shard_marker(a.out);
    }

    const Stopwatch watch;
    tiles::TileExportStats stats;
    {
        ProgressBar bar("tiles", tile_plan.size(), "tiles");
        stats = tiles::export_tiles(dem, job, *sink, &bar);
        bar.finish();
    }
    if (!mbtiles && !job.shard.whole()) write_shard_marker(a.out, job.shard);
    const double total = watch.seconds();
    const std::size_t made = stats.written + stats.empty;
    std::printf("tiles: %zu written, %zu resumed, %zu without data (zoom %d-%d, %d px, %s)\n", stats.written,
                stats.resumed, stats.empty, job.z0, job.z1, job.tile_size,
                std::string(tiles::tile_style_name(job.shading.style)).c_str());
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
    if (!a.debug_heights.empty()) write_debug_heights(dem, job, a.debug_heights, a.out);
}

}  // namespace

void add_tiles_command(CLI::App& root) {
    auto a = std::make_shared<TilesCommandArgs>();
    CLI::App* cmd = root.add_subcommand(
        "tiles",
        "Web Mercator map tiles of a shaded DEM: an XYZ directory DIR/z/x/y.png or one MBTiles file, with "
        "seamless edges and crash-safe --resume (docs/tiles.md)");
    add_dem_input_options(*cmd, a->dem);
    add_tiles_options(*cmd, a->tiles);
    cmd->add_option("-o,--out", a->out, "Output: a directory (XYZ tiles DIR/z/x/y.png) or FILE.mbtiles")->required();
    cmd->add_flag("--resume", a->resume,
                  "Continue an interrupted run with the same options: finished tiles are kept, the rest made");
    add_shard_option(*cmd, a->shard);
    cmd->add_option("--name", a->name, "MBTiles metadata name (default: the DEM file's name and the style)");
    cmd->add_option("--attribution", a->attribution, "MBTiles metadata attribution");
    cmd->add_option("--debug-heights", a->debug_heights,
                    "Also write the heights tile Z/X/Y is shaded from (1-px halo) as Z-X-Y-heights.tif beside the "
                    "tiles, for checking against gdaldem");
    cmd->callback([a] { run_tiles(*a); });
}

}  // namespace ts::app
