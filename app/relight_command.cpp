// `terrashade relight`: the same DEM under the sun and sky of many instants. Visibility and
// transfer vectors are computed once; each frame is only the sky's SH, the sun's visibility
// sweep and the per-texel shading (docs/rendering.md, "Relighting").
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/compute_device.hpp"
#include "app/interrupt_watcher.hpp"
#include "app/io_plan.hpp"
#include "app/render_options.hpp"
#include "core/render/background_writer.hpp"
#include "core/light/time_interval.hpp"
#include "core/light/utc_time.hpp"
#include "core/util/error.hpp"
#include "core/util/progress_bar.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::app {
namespace {

struct RelightArgs {
    RenderArgs render;
    std::string times;
    std::string times_file;
    std::string out_dir;
    std::string format = "png";
    int write_queue = 2;  // frames that may wait for the writer threads (memory: 12 B/pixel each)
    int writer_threads = render::kDefaultWriterThreads;
};

std::vector<light::UtcTime> read_times_file(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw input_error(path, "cannot read the times file");
    std::vector<light::UtcTime> times;
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        const auto last = line.find_last_not_of(" \t\r");
        try {
            times.push_back(light::parse_utc_time(std::string_view(line).substr(first, last - first + 1)));
        } catch (const InputError& e) {
            throw input_error(path, "line " + std::to_string(number) + ": " + e.what());
        }
    }
    if (times.empty()) throw input_error(path, "no times in the file (one ISO 8601 instant per line)");
    return times;
}

void run_relight(const RelightArgs& a) {
    if (a.times.empty() == a.times_file.empty()) throw InputError("relight: give either --times or --times-file");
    render::SceneOptions options = scene_options(a.render);
    render::Exposure exposure = exposure_of(a.render);
    IoPlan plan;
    plan_render_inputs(plan, a.render, options);
    plan.input("--times-file", a.times_file).output_directory("--out", a.out_dir);
    plan.check();
    const std::vector<light::UtcTime> times =
        a.times.empty() ? read_times_file(a.times_file) : light::parse_time_interval(a.times, 10000);
    interrupt::report_progress("frames", times.size());
    std::error_code ec;
    std::filesystem::create_directories(a.out_dir, ec);
    if (ec || !std::filesystem::is_directory(a.out_dir))
        throw input_error(a.out_dir, "cannot create the output directory");

    const dem::Dem dem = load_dem_input(a.render.dem);
    warn_if_single_line(dem);
    const ComputeDevice device(a.render.device);  // before the scene: it must outlive it
    device.apply(options);
    std::printf("visibility, transfer and sky shading on %s\n", device.name().c_str());
    const Stopwatch t0;
    std::unique_ptr<render::Scene> scene;
    {
        ProgressBar bar("visibility", std::uint64_t(dem.width) * dem.height * std::uint64_t(a.render.directions), "rays");
        render::SceneOptions with_bar = options;
        with_bar.renderer.progress = &bar;
        scene = std::make_unique<render::Scene>(dem, with_bar);
    }
    const double setup_s = t0.seconds();

    std::vector<render::SunState> suns;
    std::size_t down = 0, brightest = 0;
    for (const auto& t : times) {
        suns.push_back(scene->sun_at(t));
        if (suns.back().elevation_deg < -0.27) ++down;
        if (suns.back().elevation_deg > suns[brightest].elevation_deg) brightest = suns.size() - 1;
    }
    if (down > 0)
        std::fprintf(stderr, "terrashade: warning: the sun is below the horizon at %zu of %zu times: those frames "
                             "have sky light only\n", down, times.size());
    render::LinearImage image;
    if (exposure.automatic && a.format != "exr") {
        // One exposure for the whole sequence (from the frame with the highest sun), so dusk
        // looks darker than noon instead of flickering frame to frame.
        scene->render(suns[brightest], image);
        const double scale = render::image_exposure_scale(image, exposure);
        exposure.automatic = false;
        exposure.ev100 = std::log2(1000.0 / (1.2 * scale));
        std::printf("exposure: EV100 %.2f for every frame (auto, from %s)\n", exposure.ev100,
                    light::format_utc_time(times[brightest]).c_str());
    }
    const Stopwatch t1;
    double render_s = 0;
    int width = 0, height = 0;
    {
        // Frame k is tone-mapped, encoded and renamed into place on a writer thread while
        // frame k+1 renders (encoding a PNG takes about as long as relighting it).
        render::BackgroundWriter writer(a.write_queue, a.writer_threads);
        ProgressBar bar("relight", times.size(), "frames");
        for (std::size_t k = 0; k < times.size(); ++k) {
            const Stopwatch tf;
            scene->render(suns[k], image);
            render_s += tf.seconds();
            width = image.width, height = image.height;
            char name[64];
            std::snprintf(name, sizeof name, "frame_%04zu.%s", k, a.format.c_str());
            writer.write((std::filesystem::path(a.out_dir) / name).string(), image, exposure,
                         scene->target().georef());
            bar.advance();
        }
        writer.finish();
    }
    const double total_s = t1.seconds();
    const double px = double(width) * height * double(times.size());
    std::printf("relit %zu frames (%dx%d) into %s: visibility + transfer once %.3f s; frames %.3f s rendering "
                "(%.1f Mpx/s), %.3f s with files written (%.1f Mpx/s)\n",
                times.size(), width, height, a.out_dir.c_str(), setup_s, render_s, px / render_s * 1e-6, total_s,
                px / total_s * 1e-6);
}

}  // namespace

void add_relight_command(CLI::App& root) {
    auto a = std::make_shared<RelightArgs>();
    CLI::App* cmd = root.add_subcommand(
        "relight",
        "The same DEM relit for many instants: visibility once, then one frame per time (frame_0000.png, ...). "
        "Times with the sun below the horizon are rendered with sky light only (a warning says how many).");
    add_render_options(*cmd, a->render);
    cmd->add_option("--times", a->times, "START/END/STEP, ISO 8601 (e.g. 2025-06-21T04:00Z/2025-06-21T20:00Z/PT1H)");
    cmd->add_option("--times-file", a->times_file, "A file with one ISO 8601 instant per line (# comments)");
    cmd->add_option("-o,--out", a->out_dir, "Output directory (created if missing)")->required();
    cmd->add_option("--format", a->format, "Frame format: png, tif (8-bit sRGB, georeferenced for maps) or exr (linear)")
        ->capture_default_str()
        ->check(CLI::IsMember({"png", "tif", "exr"}));
    cmd->add_option("--write-queue", a->write_queue,
                    "Frames that may wait for the writer threads (they encode frame k while frame k+1 renders)")
        ->capture_default_str()
        ->check(CLI::Range(1, 64));
    cmd->add_option("--writer-threads", a->writer_threads,
                    "Threads encoding and writing frames, each its own frame (frames may then land out of order)")
        ->capture_default_str()
        ->check(CLI::Range(1, 64));
    cmd->callback([a] { run_relight(*a); });
}

}  // namespace ts::app
