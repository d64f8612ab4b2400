// `terrashade bench tiles DEM`: tiles per second over zooms 8-12 for each style (shading the DEM
// levels included), and in the same run the classic pipeline, `gdaldem hillshade` then
// `gdal2tiles.py`, as a ratio. The classic pipeline is skipped with a note when GDAL's tools
// are not installed (scripts/setup.sh installs them). Figures: docs/tiles.md.
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/bench/bench_command.hpp"
#include "app/dem_input.hpp"
#include "app/tiles_options.hpp"
#include "core/tiles/tile_export.hpp"
#include "core/tiles/xyz_directory.hpp"
#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::app {
namespace {
namespace fs = std::filesystem;

struct BenchTilesArgs {
    DemInput dem;
    TilesArgs tiles;
    std::vector<std::string> styles = {"hillshade", "multidirectional", "relief", "svf", "color"};
    bool classic = true;
    bool keep = false;
};

// CPU seconds (user + system) of this process, or of its finished children: the machine may be
// shared, so beside wall-clock rates the bench reports tiles per CPU-second.
double cpu_seconds(int who) {
    rusage u{};
    getrusage(who, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

bool on_path(const std::string& tool) {
    return std::system(("command -v " + tool + " > /dev/null 2>&1").c_str()) == 0;
}

std::size_t count_pngs(const fs::path& dir) {
    std::size_t n = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file() && e.path().extension() == ".png") ++n;
    return n;
}

void run_bench_tiles(const BenchTilesArgs& a) {
    TilesArgs base = a.tiles;
    if (base.zoom.empty()) base.zoom = "8-12";
    tiles::TileJob job = tile_job(base);
    for (const auto& s : a.styles) tiles::parse_tile_style(s);  // a bad name fails before any work
    const dem::Dem dem = load_dem_input(a.dem);
    const int threads = thread_count(job.shading.threads);
    const fs::path root = fs::temp_directory_path() / ("terrashade_bench_tiles_" + std::to_string(::getpid()));
    fs::create_directories(root);
    std::printf("bench tiles: %s, zooms %d-%d, %d-px tiles, %d threads\n", dem.source.c_str(), job.z0, job.z1,
                job.tile_size, threads);
    std::printf("%-17s %7s %9s %10s %9s %12s %8s %13s\n", "style", "tiles", "total_s", "tiles/s", "shade_s",
                "cut_tiles/s", "cpu_s", "tiles/cpu_s");
    double hillshade_rate = 0, hillshade_cpu_rate = 0;
    for (const auto& name : a.styles) {
        job.shading.style = tiles::parse_tile_style(name);
        const fs::path out = root / name;
        tiles::XyzDirectory sink(out, tiles::describe_job(job), false, job.z0, job.z1);
        const Stopwatch watch;
        const double cpu0 = cpu_seconds(RUSAGE_SELF);
        const tiles::TileExportStats s = tiles::export_tiles(dem, job, sink, nullptr);
        const double total = watch.seconds(), cpu = cpu_seconds(RUSAGE_SELF) - cpu0;
        const double made = double(s.written + s.empty);
        std::printf("%-17s %7zu %9.3f %10.1f %9.3f %12.1f %8.3f %13.1f\n", name.c_str(), s.written, total, made / total,
                    s.source_seconds, s.tile_seconds > 0 ? made / s.tile_seconds : 0.0, cpu, made / cpu);
        if (job.shading.style == tiles::TileStyle::hillshade) hillshade_rate = made / total, hillshade_cpu_rate = made / cpu;
        std::fflush(stdout);
    }
    if (a.classic) {
        if (!on_path("gdaldem") || !on_path("gdal2tiles.py")) {
            std::printf("classic: skipped (gdaldem or gdal2tiles.py not installed: Debian gdal-bin, python3-gdal)\n");
        } else {
            // As a user would: hillshade on the DEM's grid (-s 111120 for a lon/lat DEM), then
            // reprojected and cut by gdal2tiles with as many processes as threads here.
            const fs::path hs = root / "classic_hillshade.tif", out = root / "classic_tiles";
            const bool geographic = dem.georef.crs().is_geographic();
            const std::string dem_file = a.dem.files.front();
            const Stopwatch watch;
            const double cpu0 = cpu_seconds(RUSAGE_CHILDREN);
            const std::string hs_cmd = "gdaldem hillshade -q -compute_edges " + std::string(geographic ? "-s 111120 " : "") +
                                       "'" + dem_file + "' '" + hs.string() + "'";
            const std::string tiles_cmd = "gdal2tiles.py -q -z " + std::to_string(job.z0) + "-" + std::to_string(job.z1) +
                                          " -w none -r bilinear --processes=" + std::to_string(threads) + " '" +
                                          hs.string() + "' '" + out.string() + "' > /dev/null 2>&1";
            const double t0 = watch.seconds();
            const bool ok = std::system(hs_cmd.c_str()) == 0;
            const double t_hs = watch.seconds() - t0;
            const bool ok2 = ok && std::system(tiles_cmd.c_str()) == 0;
            const double total = watch.seconds(), cpu = cpu_seconds(RUSAGE_CHILDREN) - cpu0;
            if (!ok2) {
                std::printf("classic: failed (%s)\n", ok ? "gdal2tiles.py" : "gdaldem");
            } else {
                const std::size_t n = count_pngs(out);
                std::printf("%-17s %7zu %9.3f %10.1f %9.3f %12s %8.3f %13.1f\n", "classic(gdal)", n, total, n / total,
                            t_hs, "-", cpu, n / cpu);
                if (hillshade_rate > 0)
                    std::printf("hillshade vs classic: %.1fx the tiles per second (wall), %.1fx per CPU-second\n",
                                hillshade_rate / (n / total), hillshade_cpu_rate / (n / cpu));
            }
        }
    }
    if (!a.keep) {
        std::error_code ec;
        fs::remove_all(root, ec);
    } else {
        std::printf("tiles kept in %s\n", root.c_str());
    }
}

}  // namespace

void add_bench_tiles_command(CLI::App& bench) {
    auto a = std::make_shared<BenchTilesArgs>();
    CLI::App* cmd = bench.add_subcommand(
        "tiles", "Map tiles per second per style over zooms 8-12, and gdaldem + gdal2tiles.py as a ratio");
    add_dem_input_options(*cmd, a->dem);
    add_tiles_options(*cmd, a->tiles, false);
    cmd->add_option("--zoom", a->tiles.zoom, "Zooms Z0-Z1 (default 8-12)");
    cmd->add_option("--styles", a->styles, "Styles to measure (default all)")->delimiter(',');
    cmd->add_flag("!--no-classic", a->classic, "Skip the gdaldem + gdal2tiles.py pipeline");
    cmd->add_flag("--keep", a->keep, "Keep the tiles (printed path) to look at them");
    cmd->callback([a] { run_bench_tiles(*a); });
}

}  // namespace ts::app
