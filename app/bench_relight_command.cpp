// `terrashade bench relight DEM`: how fast relighting is once the visibility is known.
// Prints the one-time cost (horizons + log-SH, transfer vectors), the per-frame shading rate
// (sky SH projection + sun visibility sweep + per-texel shading, no file written) as
// `N Mpx/s`, the end-to-end rate with a PNG written per frame, and in the same run the
// baseline: a classic hillshade (local shading, no shadows, no sky) of the same DEM.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "app/command.hpp"
#include "app/render_options.hpp"
#include "core/shading/hillshade.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"

namespace ts::app {
namespace {

struct BenchRelightArgs {
    RenderArgs render;
    int frames = 24;
    std::string out_dir;
};

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// A day's arc for frame k of n: the sun from east (azimuth 90) over the south to west (270),
// elevation 8 -> 60 -> 8 degrees, so frames have long and short shadows alike.
render::SunState sun_of_frame(int k, int n) {
    const double u = n > 1 ? double(k) / (n - 1) : 0.5;
    const double pi = 3.14159265358979323846;
    return {90.0 + 180.0 * u, 8.0 + 52.0 * std::sin(pi * u)};
}

void run_bench_relight(const BenchRelightArgs& a) {
    if (a.frames < 1) throw InputError("--frames must be >= 1");
    const render::SceneOptions options = scene_options(a.render);
    const render::Exposure exposure = exposure_of(a.render);
    const dem::Dem dem = load_dem_input(a.render.dem);
    const std::size_t texels = std::size_t(dem.width) * dem.height;

    auto t0 = Clock::now();
    render::Scene scene(dem, options);
    const double setup_s = seconds_since(t0);

    // Warm-up frame (first-touch page faults, lazy tables), not timed.
    render::LinearImage image;
    scene.render(sun_of_frame(0, a.frames), image);
    const double pixels = double(image.width) * image.height;

    double sky_s = 0, sun_s = 0, shade_s = 0;
    t0 = Clock::now();
    for (int k = 0; k < a.frames; ++k) {
        scene.render(sun_of_frame(k, a.frames), image);
        const auto& t = scene.renderer().last_timings();
        sky_s += t.sky_s, sun_s += t.sun_visibility_s, shade_s += t.shading_s;
    }
    const double frames_s = seconds_since(t0);

    const std::filesystem::path dir =
        a.out_dir.empty() ? std::filesystem::temp_directory_path() / ("ts_bench_relight_" + std::to_string(::getpid()))
                          : std::filesystem::path(a.out_dir);
    std::filesystem::create_directories(dir);
    t0 = Clock::now();
    for (int k = 0; k < a.frames; ++k) {
        scene.render(sun_of_frame(k, a.frames), image);
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", k);
        render::write_image((dir / name).string(), image, exposure, nullptr);
    }
    const double files_s = seconds_since(t0);
    if (a.out_dir.empty()) std::filesystem::remove_all(dir);

    // Baseline in the same run: the classic hillshade, one light, no shadows, no sky.
    const terrain::HeightGrid grid = terrain::metric_view(dem);
    shading::HillshadeOptions ho;
    ho.threads = a.render.threads;
    shading::hillshade(grid, ho);
    t0 = Clock::now();
    for (int k = 0; k < a.frames; ++k) {
        ho.azimuth_deg = sun_of_frame(k, a.frames).azimuth_deg;
        ho.altitude_deg = sun_of_frame(k, a.frames).elevation_deg;
        shading::hillshade(grid, ho);
    }
    const double hill_s = seconds_since(t0);

    const double n = a.frames;
    std::printf("DEM %dx%d (%zu texels), %s view %dx%d, %d frames, %d threads\n", dem.width, dem.height, texels,
                options.view == render::ViewKind::map ? "map" : "perspective", image.width, image.height, a.frames,
                thread_count(a.render.threads));
    std::printf("one-time: visibility (exact horizons, %d directions, log-SH) %.3f s + transfer vectors %.3f s "
                "(%zu specular, %zu water texels)\n",
                a.render.directions, scene.renderer().visibility_seconds(), scene.renderer().transfer_seconds(),
                scene.renderer().specular_texels(), scene.renderer().water_texels());
    std::printf("per frame: sky SH + sky table %.2f ms, sun visibility sweep %.2f ms, shading %.2f ms, "
                "total %.2f ms\n",
                sky_s / n * 1e3, sun_s / n * 1e3, shade_s / n * 1e3, frames_s / n * 1e3);
    std::printf("relight: %.1f Mpx/s (per-frame work after the visibility pass: sky SH, sun sweep, shading%s)\n",
                pixels * n / frames_s * 1e-6, options.view == render::ViewKind::map ? "" : ", view composition");
    std::printf("end-to-end with files: %.1f Mpx/s (%.2f ms per frame incl. tone mapping and PNG writing)\n",
                pixels * n / files_s * 1e-6, files_s / n * 1e3);
    std::printf("baseline hillshade (local, no shadows, no sky): %.1f Mpx/s\n", double(texels) * n / hill_s * 1e-6);
    std::printf("with the one-time cost over %d frames: %.1f Mpx/s\n", a.frames,
                pixels * n / (frames_s + setup_s) * 1e-6);
}

}  // namespace

void add_bench_relight_command(CLI::App& bench) {
    auto a = std::make_shared<BenchRelightArgs>();
    CLI::App* cmd = bench.add_subcommand(
        "relight", "Relighting throughput after the visibility pass (Mpx/s), end to end with files, and a hillshade "
                   "baseline in the same run");
    add_render_options(*cmd, a->render);
    cmd->add_option("--frames", a->frames, "Frames to time (sun over a day's arc)")->capture_default_str()->check(
        CLI::Range(1, 100000));
    cmd->add_option("--keep", a->out_dir, "Keep the written frames in this directory (default: a temp dir, removed)");
    cmd->callback([a] { run_bench_relight(*a); });
}

}  // namespace ts::app
