// `terrashade plan relight`: the frames of a relight job, the shards that fit it into a wall
// time and the storage, from a measured setup and a few measured frames (or a given rate).
// docs/scale.md.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>
#include <system_error>

#include "app/compute_device.hpp"
#include "app/io_plan.hpp"
#include "app/options/night_option.hpp"
#include "app/render_options.hpp"
#include "app/wall_time.hpp"
#include "core/light/time_interval.hpp"
#include "core/render/background_writer.hpp"
#include "core/render/render_scene.hpp"
#include "core/util/error.hpp"
#include "core/util/stopwatch.hpp"
#include "core/util/temp_files.hpp"

namespace ts::app {
namespace {

struct PlanRelightArgs {
    RenderArgs render;
    std::string times;
    std::string format = "png";
    std::string wall_time = "1h";
    double rate = 0;
    double setup_seconds = -1;
    int sample = 3;
    NightArgs night;  // the frames relight renders: night left out unless --night include
};

void run_plan_relight(const PlanRelightArgs& a) {
    render::SceneOptions options = scene_options(a.render);
    const render::Exposure exposure = exposure_of(a.render);
    const double wall_s = parse_wall_time(a.wall_time);
    IoPlan plan;
    plan_render_inputs(plan, a.render, options);
    plan.check();
    if (a.rate < 0) throw InputError("--rate: frames per second per shard, > 0");
    const bool skip_night = skips_night(a.night);
    const auto instants = light::parse_time_interval(a.times, 10000000);
    const dem::Dem dem = load_dem_input(a.render.dem);
    attach_meshes(a.render, dem, options);
    // The frames relight will render: without the night instants, as it leaves them out.
    std::vector<light::UtcTime> times;
    const render::SunSite site = render::sun_site(dem);
    for (const auto& t : instants)
        if (!skip_night || render::sun_at(site, t).elevation_deg >= kNightElevationDeg) times.push_back(t);
    if (times.empty()) throw InputError("plan relight: the sun is below -6 degrees (night) at every instant: nothing to render");
    std::printf("relight of %s: %zu frames (%dx%d texels)", a.render.dem.files.front().c_str(), times.size(), dem.width,
                dem.height);
    if (times.size() < instants.size()) std::printf(", %zu night instants left out", instants.size() - times.size());
    std::printf("\n");

    double setup_s = std::max(0.0, a.setup_seconds), frames_per_s = a.rate, frame_bytes = 0;
    const bool measure = a.rate == 0 || a.setup_seconds < 0;
    if (measure) {
        if (a.sample < 1) throw InputError("--sample: at least 1 frame to measure, or give --rate and --setup-seconds");
        const ComputeDevice device(a.render.device);
        device.apply(options);
        const Stopwatch t0;
        render::Scene scene(dem, options);
        if (a.setup_seconds < 0) setup_s = t0.seconds();
        // The sample frames are written as relight writes them, into a temporary folder.
        const std::filesystem::path dir = temp_files::sibling_for(std::filesystem::temp_directory_path() / "plan");
        temp_files::track_directory(dir);
        std::filesystem::create_directory(dir);
        const int n = int(std::min<std::size_t>(std::size_t(a.sample), times.size()));
        const Stopwatch t1;
        {
            render::BackgroundWriter writer(2, render::kDefaultWriterThreads);
            render::LinearImage image;
            for (int k = 0; k < n; ++k) {
                // Spread over the series: dawn and noon frames cost the same, but compress differently.
                const auto& t = times[std::size_t(k) * (times.size() - 1) / std::max(1, n - 1)];
                scene.render(scene.sun_at(t), image);
                writer.write((dir / ("frame_" + std::to_string(k) + "." + a.format)).string(), image, exposure,
                             scene.target().georef());
            }
            writer.finish();
        }
        const double frames_s = t1.seconds();
        std::uintmax_t bytes = 0;
        std::error_code ec;
        for (const auto& f : std::filesystem::directory_iterator(dir)) bytes += f.file_size(ec);
        std::filesystem::remove_all(dir, ec);
        temp_files::forget_directory(dir);
        frame_bytes = double(bytes) / n;
        if (a.rate == 0) frames_per_s = n / std::max(frames_s, 1e-9);
        std::printf("sample: setup (visibility, transfer) %.2f s, %d frames in %.2f s (%.2f frames/s), %.0f bytes "
                    "each\n",
                    setup_s, n, frames_s, n / std::max(frames_s, 1e-9), frame_bytes);
    }
    if (frame_bytes == 0) frame_bytes = double(dem.width) * dem.height * 3 * 0.5;  // 8-bit RGB PNG, ~2:1
    const double work_s = double(times.size()) / frames_per_s;
    const std::int64_t shards = shards_for_wall_time(work_s, setup_s, wall_s);
    if (shards == 0)
        throw InputError("plan relight: the setup alone takes " + format_duration(setup_s) +
                         " per shard, more than --wall-time " + a.wall_time);
    const std::int64_t used = std::min<std::int64_t>(shards, std::int64_t(times.size()));
    const double shard_s = setup_s + work_s / double(used);
    std::printf("one process: %s (%s setup + %s frames)\n", format_duration(setup_s + work_s).c_str(),
                format_duration(setup_s).c_str(), format_duration(work_s).c_str());
    std::printf("shards: %lld for --wall-time %s: ~%zu frames and %s each, %.2f shard-hours in all (node-hours with one shard per node)\n",
                static_cast<long long>(used), a.wall_time.c_str(), times.size() / std::size_t(used),
                format_duration(shard_s).c_str(), double(used) * shard_s / 3600.0);
    std::printf("slurm: sbatch --array=0-%lld --time=%s (scripts/slurm_shards.sh)\n", static_cast<long long>(used - 1),
                slurm_time(wall_s).c_str());
    std::printf("storage: %s (%s)\n", format_bytes(frame_bytes * double(times.size())).c_str(),
                measure ? "bytes per frame from the sample" : "about 1.5 bytes per texel assumed: no sample");
}

}  // namespace

void add_plan_relight_command(CLI::App& plan) {
    auto a = std::make_shared<PlanRelightArgs>();
    CLI::App* cmd = plan.add_subcommand("relight", "The work of a `relight` job: frames, shards for a wall time, "
                                                   "storage (the same DEM and render options as `relight`)");
    add_render_options(*cmd, a->render);
    cmd->add_option("--times", a->times, "START/END/STEP, ISO 8601, as relight --times")->required();
    cmd->add_option("--format", a->format, "Frame format of the sample: png, tif or exr")
        ->capture_default_str()
        ->check(CLI::IsMember({"png", "tif", "exr"}));
    cmd->add_option("--wall-time", a->wall_time, "Wall time one shard may take (2h, 1h30m, 45m, HH:MM:SS)")
        ->capture_default_str();
    cmd->add_option("--rate", a->rate, "Frames per second of one shard, instead of the measured sample's");
    cmd->add_option("--setup-seconds", a->setup_seconds, "Setup (visibility, transfer) of one shard, instead of measured");
    cmd->add_option("--sample", a->sample, "Frames to render (and throw away) to measure")->capture_default_str();
    add_night_options(*cmd, a->night);
    cmd->callback([a] { run_plan_relight(*a); });
}

}  // namespace ts::app
