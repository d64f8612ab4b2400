// `terrashade bench tiles DEM`: tiles per second over zooms 8-12 for each style (shading the DEM
// levels included), and in the same run the classic pipeline, `gdaldem hillshade` then
// `gdal2tiles.py`, as a ratio. The classic pipeline is skipped with a note when GDAL's tools
// are not installed (scripts/setup.sh installs them). Figures: docs/tiles.md.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/bench/bench_command.hpp"
#include "app/bench/process_usage.hpp"
#include "app/bench/shell_command.hpp"
#include "app/bench/study/synthetic_mosaic.hpp"
#include "app/bench/tile_knobs_study.hpp"
#include "app/dem_input.hpp"
#include "app/io_plan.hpp"
#include "app/tiles_options.hpp"
#include "core/raster/raster_writer.hpp"
#include "core/raster/srgb.hpp"
#include "app/bench/study/reference_relief.hpp"
#include "core/tiles/shade_source.hpp"
#include "core/tiles/tile_export.hpp"
#include "core/tiles/xyz_directory.hpp"
#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/stopwatch.hpp"
#include "app/options/within_range.hpp"

namespace ts::app {
namespace {
namespace fs = std::filesystem;

struct BenchTilesArgs {
    DemInput dem;
    TilesArgs tiles;
    std::vector<std::string> styles = {"hillshade", "multidirectional", "relief", "svf", "color"};
    bool classic = true;
    bool keep = false;
    std::vector<double> reference_at;  // LON,LAT: relief against the ray-traced reference there
    int reference_texels = 96;
    int reference_azimuths = 720;
    std::string reference_out;
    bool knobs = false;  // the tiles' knobs for the report (tile_knobs_study.hpp)
    std::string csv;
};

std::uint8_t srgb_code(float linear) {
    return std::uint8_t(std::lround(255.0f * raster::srgb_oetf(std::clamp(linear, 0.0f, 1.0f))));
}

// `relief` as the tiles are cut from it (the source of the last zoom's level and exaggeration)
// against the ray-traced reference on an N x N window of that level around LON,LAT: errors in
// display-linear values and in the tiles' sRGB codes; both as grey PNGs in --reference-out.
void run_reference(const BenchTilesArgs& a, const dem::Dem& dem, tiles::TileJob job) {
    job.shading.style = tiles::find_tile_style("relief");
    const int pixel_zoom = job.z1 + tiles::tile_size_shift(job.tile_size);
    const tiles::ZoomShading zs = tiles::zoom_shading(dem, job, pixel_zoom);
    const Stopwatch watch;
    const tiles::ShadeSource source = tiles::make_shade_source(dem, job.shading, zs.level, zs.vertical_scale);
    const double relief_s = watch.seconds();
    const glm::dvec2 px = dem.georef.lonlat_to_pixel({a.reference_at[0], a.reference_at[1]});
    const int n = a.reference_texels, scale = 1 << zs.level;
    tiles::LevelWindow w;
    w.width = std::min(n, source.width), w.height = std::min(n, source.height);
    w.col0 = std::clamp(int(px.x / scale) - w.width / 2, 0, source.width - w.width);
    w.row0 = std::clamp(int(px.y / scale) - w.height / 2, 0, source.height - w.height);
    render::ReferenceOptions ro;
    ro.azimuths = a.reference_azimuths;
    ro.threads = job.shading.threads;
    const Stopwatch watch_ref;
    const std::vector<float> ref = tiles::reference_relief(dem, job.shading, zs.level, zs.vertical_scale, w, ro);
    const double ref_s = watch_ref.seconds();
    std::vector<std::uint8_t> got_png, ref_png;
    double sum = 0, sum2 = 0, code2 = 0;
    std::vector<int> code_err;
    for (int r = 0; r < w.height; ++r)
        for (int c = 0; c < w.width; ++c) {
            const float g = source.values[std::size_t(w.row0 + r) * std::size_t(source.width) + std::size_t(w.col0 + c)];
            const float b = ref[std::size_t(r) * std::size_t(w.width) + std::size_t(c)];
            got_png.push_back(srgb_code(g)), ref_png.push_back(srgb_code(std::isnan(b) ? 0.0f : b));
            if (std::isnan(b) || std::isnan(g)) continue;
            sum += g - b, sum2 += double(g - b) * (g - b);
            const int e = int(got_png.back()) - int(ref_png.back());
            code2 += double(e) * e;
            code_err.push_back(std::abs(e));
        }
    const double m = double(code_err.size());
    std::sort(code_err.begin(), code_err.end());
    std::printf("reference: relief at zoom %d (level %d, vertical x%.3g) vs ray-traced (%d azimuths) on %dx%d texels "
                "at col %d row %d\n", job.z1, zs.level, zs.vertical_scale, ro.azimuths, w.width, w.height, w.col0, w.row0);
    std::printf("reference: display-linear bias %+.4f rmse %.4f (flat open ground = %.2f); sRGB codes rmse %.2f, "
                "median |e| %d, p95 %d, max %d; time %.1f s relief (whole level), %.1f s reference (window)\n",
                sum / m, std::sqrt(sum2 / m), double(tiles::kReliefFlatGrey), std::sqrt(code2 / m),
                code_err[code_err.size() / 2], code_err[std::size_t(0.95 * (m - 1))], code_err.back(), relief_s, ref_s);
    if (!a.reference_out.empty()) {
        fs::create_directories(a.reference_out);
        raster::write_u8_image(fs::path(a.reference_out) / "relief.png", w.width, w.height, 1, got_png.data(), nullptr);
        raster::write_u8_image(fs::path(a.reference_out) / "reference.png", w.width, w.height, 1, ref_png.data(), nullptr);
        std::printf("reference: wrote relief.png and reference.png in %s\n", a.reference_out.c_str());
    }
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
    for (const auto& s : a.styles) {
        tiles::parse_tile_style(s);  // a bad name fails before any work
        // Its sun tables and ramp come from the days `tiles` is given (a year's: seconds).
        if (s == "insolation")
            throw InputError("bench tiles --styles: time insolation tiles with `terrashade tiles --style insolation` "
                             "(it prints its shading and tile times)");
    }
    if (a.knobs && a.csv.empty()) throw InputError("bench tiles --knobs: give --csv FILE");
    if (!a.csv.empty() && !a.knobs) throw InputError("bench tiles: --csv goes with --knobs");
    IoPlan plan;
    for (const std::string& f : a.dem.files)
        if (!f.starts_with("synthetic:")) plan.input("DEM", f);
    plan.output_directory("--reference-out", a.reference_out);
    plan.output("--csv", a.csv, {".csv"});
    plan.check();
    const std::string& first = a.dem.files.front();
    const bool synthetic = first.starts_with("synthetic:");
    int synthetic_n = 0;
    if (synthetic && (std::sscanf(first.c_str(), "synthetic:%d", &synthetic_n) != 1))
        throw InputError(first + ": give synthetic:N (an N x N mosaic)");
    const dem::Dem dem = synthetic ? synthetic_mosaic(synthetic_n, job.shading.threads) : load_dem_input(a.dem);
    const int threads = thread_count(job.shading.threads);
    if (!a.reference_at.empty()) {
        run_reference(a, dem, job);
        return;
    }
    if (a.knobs) {
        run_tile_knobs_study(dem, job, a.csv);
        return;
    }
    const fs::path root = fs::temp_directory_path() / ("terrashade_bench_tiles_" + std::to_string(::getpid()));
    fs::create_directories(root);
    std::printf("bench tiles: %s, zooms %d-%d, %d-px tiles, %d threads\n", dem.source.c_str(), job.z0, job.z1,
                job.tile_size, threads);
    std::printf("DEM %dx%d (%.2f GB of heights); peak RSS with it loaded %.2f GB\n", dem.width, dem.height,
                double(dem.z.size()) * 4 / 1e9, peak_rss_gb());
    std::printf("%-17s %7s %9s %10s %9s %12s %8s %13s %11s\n", "style", "tiles", "total_s", "tiles/s", "shade_s",
                "cut_tiles/s", "cpu_s", "tiles/cpu_s", "peak_rss_GB");
    double hillshade_rate = 0, hillshade_cpu_rate = 0;
    for (const auto& name : a.styles) {
        job.shading.style = &tiles::parse_tile_style(name);
        // --relief-contrast is relief's alone; the other styles of the run keep theirs.
        job.shading.relief_contrast = job.shading.style->takes_relief_contrast() ? a.tiles.relief_contrast : 1.0;
        const fs::path out = root / name;
        tiles::XyzDirectory sink(out, tiles::describe_job(job), tiles::XyzDirectory::Existing::refuse, job.z0, job.z1);
        const Stopwatch watch;
        const double cpu0 = cpu_seconds(RUSAGE_SELF);
        const tiles::TileExportStats s = tiles::export_tiles(dem, job, sink, nullptr);
        const double total = watch.seconds(), cpu = cpu_seconds(RUSAGE_SELF) - cpu0;
        const double made = double(s.written + s.empty);
        // Peak RSS is the process's so far: with several styles, the largest of them and before.
        std::printf("%-17s %7zu %9.3f %10.1f %9.3f %12.1f %8.3f %13.1f %11.2f\n", name.c_str(), s.written, total,
                    made / total, s.source_seconds, s.tile_seconds > 0 ? made / s.tile_seconds : 0.0, cpu, made / cpu,
                    peak_rss_gb());
        if (job.shading.style->name() == "hillshade") hillshade_rate = made / total, hillshade_cpu_rate = made / cpu;
        std::fflush(stdout);
    }
    if (a.classic && synthetic) {
        std::printf("classic: skipped (a synthetic mosaic has no file to give gdaldem)\n");
    } else if (a.classic) {
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
    add_dem_input_options(*cmd, a->dem);  // or synthetic:N (synthetic_mosaic.hpp)
    add_tiles_options(*cmd, a->tiles, false);
    cmd->add_option("--zoom", a->tiles.zoom, "Zooms Z0-Z1 (default 8-12)");
    cmd->add_option("--styles", a->styles, "Styles to measure (default all but insolation)")->delimiter(',');
    cmd->add_flag("!--no-classic", a->classic, "Skip the gdaldem + gdal2tiles.py pipeline");
    cmd->add_flag("--knobs", a->knobs,
                  "Relief's block size, halo and far field against the level shaded whole, and 512- against "
                  "256-px tiles (time and sRGB-code error at the last zoom; needs --csv; bench report runs it)");
    cmd->add_option("--csv", a->csv, "--knobs: the rows (knob,value,is_default,seconds,rms_codes,max_codes)");
    cmd->add_flag("--keep", a->keep, "Keep the tiles (printed path) to look at them");
    cmd->add_option("--reference", a->reference_at,
                    "LON,LAT: instead of the speeds, relief (at the last zoom's level) against the ray-traced "
                    "reference on a window there")
        ->expected(2)->delimiter(',');
    cmd->add_option("--reference-texels", a->reference_texels, "--reference: window side, level texels")
        ->capture_default_str()->check(within(4, 1024));
    cmd->add_option("--reference-azimuths", a->reference_azimuths, "--reference: raymarched horizon azimuths")
        ->capture_default_str()->check(within(16, 8192));
    cmd->add_option("--reference-out", a->reference_out, "--reference: directory for relief.png and reference.png");
    cmd->callback([a] { run_bench_tiles(*a); });
}

}  // namespace ts::app
