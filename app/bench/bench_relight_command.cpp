// `terrashade bench relight DEM`: how fast relighting is once the visibility is known.
// Prints the one-time cost (horizons + log-SH, transfer vectors), the per-frame shading rate
// (sky SH projection + sun visibility sweep + per-texel shading, no file written) as
// `N Mpx/s`, the end-to-end rate with a PNG written per frame (on writer threads, as `relight`
// does, and one after the other for comparison) next to the shading-only rate, the mean PNG
// size, and in the same run the baseline: a classic hillshade (local shading, no shadows, no
// sky) of the same DEM.
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
#include "app/compute_device.hpp"
#include "app/render_options.hpp"
#include "core/raster/raster_writer.hpp"
#include "core/render/background_writer.hpp"
#include "core/render/hillshade.hpp"
#include "core/render/render_backend.hpp"
#include "core/render/tone_map.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/temp_files.hpp"
#include "core/util/stopwatch.hpp"
#include "app/options/within_range.hpp"

namespace ts::app {
namespace {

struct BenchRelightArgs {
    RenderArgs render;
    int frames = 24;
    std::string out_dir;
    int write_queue = 2;  // frames waiting for the writer threads
    int writer_threads = render::kDefaultWriterThreads;
    bool compare_cpu = false;  // --compare-cpu: also time the CPU path in the same run
    bool compare_unfused = false;  // --compare-unfused: the shading stage against the CPU backend's
    bool compare_devices = false;  // --compare-devices: the default path, --device cpu and vulkan
};

// A day's arc for frame k of n: the sun from east (azimuth 90) over the south to west (270),
// elevation 8 -> 60 -> 8 degrees, so frames have long and short shadows alike.
render::SunState sun_of_frame(int k, int n) {
    const double u = n > 1 ? double(k) / (n - 1) : 0.5;
    return {90.0 + 180.0 * u, 8.0 + 52.0 * std::sin(kPi * u)};
}

// --compare-cpu: the one-time stages and the per-frame work of the CPU path (no backend: the
// fused CPU shading) against this run's device path, frames interleaved so the machine's load
// hits both alike.
struct FrameSums {
    double sky_s = 0, sun_s = 0, shade_s = 0, total_s = 0;
    void add(render::Scene& scene, const render::SunState& sun, render::LinearImage& image) {
        const Stopwatch t0;
        scene.render(sun, image);
        total_s += t0.seconds();
        const auto& t = scene.renderer().last_timings();
        sky_s += t.sky_s, sun_s += t.sun_visibility_s, shade_s += t.shading_s;
    }
};

void compare_with_cpu(const dem::Dem& dem, render::SceneOptions options, int frames, render::Scene& device_scene,
                      double device_setup_s) {
    options.renderer.backend = nullptr;
    options.renderer.visibility = nullptr;
    const Stopwatch t0;
    render::Scene scene(dem, options);
    const double setup_s = t0.seconds();
    render::LinearImage image;
    scene.render(sun_of_frame(0, frames), image);  // warm-up, as for the device
    FrameSums dev, cpu;
    for (int k = 0; k < frames; ++k) {
        dev.add(device_scene, sun_of_frame(k, frames), image);
        cpu.add(scene, sun_of_frame(k, frames), image);
    }
    const double n = frames;
    const auto& dr = device_scene.state();
    const auto& cr = scene.state();
    std::printf("cpu one-time: visibility %.3f s + transfer %.3f s (setup %.3f s)\n", cr.visibility_seconds(),
                cr.transfer_seconds(), setup_s);
    for (const auto& [name, f] : {std::pair{"device", dev}, std::pair{"cpu", cpu}})
        std::printf("%s per frame (interleaved): sky SH + sky table %.2f ms, sun visibility sweep %.2f ms, shading "
                    "%.2f ms, total %.2f ms; relight %.1f Mpx/s\n",
                    name, f.sky_s / n * 1e3, f.sun_s / n * 1e3, f.shade_s / n * 1e3, f.total_s / n * 1e3,
                    double(image.width) * image.height * n / f.total_s * 1e-6);
    std::printf("device / cpu time: visibility %.2f, transfer %.2f, setup %.2f, shading per frame %.2f, frame %.2f\n",
                dr.visibility_seconds() / cr.visibility_seconds(), dr.transfer_seconds() / cr.transfer_seconds(),
                device_setup_s / setup_s, dev.shade_s / cpu.shade_s, dev.total_s / cpu.total_s);
}

// --compare-unfused: the shading stage of this run's renderer against the CPU RenderBackend's
// (shade_transfer over the 16 fp32 planes of T_d, then the sun + albedo pass: the per-frame
// shading before it was fused), frames interleaved so the machine's load hits both alike.
void compare_unfused(const dem::Dem& dem, render::SceneOptions options, int frames, render::Scene& scene) {
    const std::unique_ptr<render::RenderBackend> cpu = render::make_cpu_backend(options.renderer.threads);
    options.renderer.backend = cpu.get();
    render::Scene unfused(dem, options);
    render::LinearImage image;
    unfused.render(sun_of_frame(0, frames), image);  // warm-up
    double s_this = 0, s_unfused = 0, min_this = 1e30, min_unfused = 1e30;
    for (int k = 0; k < frames; ++k) {
        scene.render(sun_of_frame(k, frames), image);
        const double a = scene.renderer().last_timings().shading_s;
        unfused.render(sun_of_frame(k, frames), image);
        const double b = unfused.renderer().last_timings().shading_s;
        s_this += a, s_unfused += b, min_this = std::min(min_this, a), min_unfused = std::min(min_unfused, b);
    }
    std::printf("shading stage, frames interleaved: this run's path %.2f ms (fastest %.2f), unfused CPU backend "
                "(16 fp32 planes, then sun + albedo) %.2f ms (fastest %.2f): %.2fx (fastest %.2fx)\n",
                s_this / frames * 1e3, min_this * 1e3, s_unfused / frames * 1e3, min_unfused * 1e3, s_unfused / s_this,
                min_unfused / min_this);
}

// --compare-devices: the whole job (one-time stages, then frames written as PNGs on the writer
// thread, as `relight` does) on the default path (--device auto), the CPU and the Vulkan
// device, one after the other in the same run.
void compare_devices(const BenchRelightArgs& a, const dem::Dem& dem, const render::Exposure& exposure) {
    struct PathTime {
        std::string label, name;
        double setup_s = 0, frames_s = 0, files_s = 0, pixels = 0;
        double total() const { return setup_s + files_s; }
    };
    std::vector<PathTime> paths;
    const auto dir = std::filesystem::temp_directory_path() / ("ts_bench_devices_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    if (a.out_dir.empty()) temp_files::track_directory(dir);  // an interrupt removes it too
    for (const std::string label : {"default", "cpu", "vulkan"}) {
        DeviceArgs args;
        args.device = label == "default" ? "auto" : label;
        std::unique_ptr<ComputeDevice> device;
        try {
            device = std::make_unique<ComputeDevice>(args);
        } catch (const InputError& e) {
            std::printf("  %-8s not run: %s\n", label.c_str(), e.what());
            continue;
        }
        render::SceneOptions options = scene_options(a.render);
        device->apply(options);
        PathTime p{label, device->name()};
        Stopwatch t0;
        render::Scene scene(dem, options);
        p.setup_s = t0.seconds();
        render::LinearImage image;
        scene.render(sun_of_frame(0, a.frames), image);  // warm-up
        p.pixels = double(image.width) * image.height * a.frames;
        t0.restart();
        for (int k = 0; k < a.frames; ++k) scene.render(sun_of_frame(k, a.frames), image);
        p.frames_s = t0.seconds();
        t0.restart();
        {
            render::BackgroundWriter writer(a.write_queue, a.writer_threads);
            for (int k = 0; k < a.frames; ++k) {
                scene.render(sun_of_frame(k, a.frames), image);
                writer.write((dir / ("frame_" + std::to_string(k) + ".png")).string(), image, exposure, nullptr);
            }
            writer.finish();
        }
        p.files_s = t0.seconds();
        paths.push_back(p);
    }
    std::filesystem::remove_all(dir);
    std::printf("paths, one after the other (%d frames each, PNG files on the writer thread):\n", a.frames);
    double fastest = 0;
    for (const auto& p : paths) {
        if (p.label != "default" && (fastest == 0 || p.total() < fastest)) fastest = p.total();
        std::printf("  %-8s on %-40s one-time %.3f s, frames %.2f ms (%.1f Mpx/s), with files %.2f ms (%.1f Mpx/s), "
                    "job %.3f s\n",
                    p.label.c_str(), p.name.c_str(), p.setup_s, p.frames_s / a.frames * 1e3, p.pixels / p.frames_s * 1e-6,
                    p.files_s / a.frames * 1e3, p.pixels / p.files_s * 1e-6, p.total());
    }
    if (!paths.empty() && paths[0].label == "default" && fastest > 0)
        std::printf("  default / fastest path, whole job: %.2f\n", paths[0].total() / fastest);
}

void run_bench_relight(const BenchRelightArgs& a) {
    if (a.frames < 1) throw InputError("--frames must be >= 1");
    render::SceneOptions options = scene_options(a.render);
    const render::Exposure exposure = exposure_of(a.render);
    IoPlan plan;
    plan_render_inputs(plan, a.render, options);
    plan.output_directory("--keep", a.out_dir);
    plan.check();
    const dem::Dem dem = load_dem_input(a.render.dem);
    const ComputeDevice device(a.render.device);  // before the scene: it must outlive it
    device.apply(options);
    const std::size_t texels = std::size_t(dem.width) * dem.height;

    Stopwatch t0;
    render::Scene scene(dem, options);
    const double setup_s = t0.seconds();

    // Warm-up frame (first-touch page faults, lazy tables), not timed.
    render::LinearImage image;
    scene.render(sun_of_frame(0, a.frames), image);
    const double pixels = double(image.width) * image.height;

    double sky_s = 0, sun_s = 0, shade_s = 0;
    double cpu0 = cpu_seconds();
    t0.restart();
    for (int k = 0; k < a.frames; ++k) {
        scene.render(sun_of_frame(k, a.frames), image);
        const auto& t = scene.renderer().last_timings();
        sky_s += t.sky_s, sun_s += t.sun_visibility_s, shade_s += t.shading_s;
    }
    const double frames_s = t0.seconds(), frames_cpu_s = cpu_seconds() - cpu0;

    const std::filesystem::path dir =
        a.out_dir.empty() ? std::filesystem::temp_directory_path() / ("ts_bench_relight_" + std::to_string(::getpid()))
                          : std::filesystem::path(a.out_dir);
    std::filesystem::create_directories(dir);
    if (a.out_dir.empty()) temp_files::track_directory(dir);  // an interrupt removes it too
    // Each phase writes new files: replacing a file by rename makes ext4 (auto_da_alloc) start
    // writing the new one back at once, a cost a fresh output folder does not pay.
    auto frame_path = [&](int k, const char* phase = "frame") {
        char name[48];
        std::snprintf(name, sizeof name, "%s_%04d.png", phase, k);
        return (dir / name).string();
    };
    // As `relight` writes: frame k encoded on a writer thread while frame k+1 renders.
    cpu0 = cpu_seconds();
    t0.restart();
    {
        render::BackgroundWriter writer(a.write_queue, a.writer_threads);
        for (int k = 0; k < a.frames; ++k) {
            scene.render(sun_of_frame(k, a.frames), image);
            writer.write(frame_path(k), image, exposure, nullptr);
        }
        writer.finish();
    }
    const double files_s = t0.seconds(), files_cpu_s = cpu_seconds() - cpu0;
    // The same frames rendered and written one after the other (the overlap's baseline).
    t0.restart();
    for (int k = 0; k < a.frames; ++k) {
        scene.render(sun_of_frame(k, a.frames), image);
        render::write_image(frame_path(k, "serial"), image, exposure, nullptr);
    }
    const double files_serial_s = t0.seconds();
    // Where a written frame's time goes, on the last frame (one thread, in this run).
    constexpr int kRepeats = 8;
    double exposure_ms = 0, tone_ms = 0, png_ms = 0;
    {
        for (int r = 0; r < kRepeats; ++r) {
            Stopwatch t;
            const double scale = render::image_exposure_scale(image, exposure);
            exposure_ms += t.milliseconds() / kRepeats;
            t.restart();
            const std::vector<std::uint8_t> bytes = render::tone_map_to_srgb8(image.rgb.data(), image.rgb.size(), scale);
            tone_ms += t.milliseconds() / kRepeats;
            t.restart();
            raster::write_u8_image(frame_path(r, "parts"), image.width, image.height, 3, bytes.data(), nullptr);
            png_ms += t.milliseconds() / kRepeats;
        }
    }
    std::uintmax_t file_bytes = 0;
    for (int k = 0; k < a.frames; ++k) file_bytes += std::filesystem::file_size(frame_path(k));
    if (a.out_dir.empty()) {
        std::filesystem::remove_all(dir);
        temp_files::forget_directory(dir);
    } else {  // keep the frames, not the timing copies
        for (int k = 0; k < a.frames; ++k) std::filesystem::remove(frame_path(k, "serial"));
        for (int r = 0; r < kRepeats; ++r) std::filesystem::remove(frame_path(r, "parts"));
    }

    // Baseline in the same run: the classic hillshade, one light, no shadows, no sky.
    const terrain::HeightGrid grid = terrain::metric_view(dem);
    render::HillshadeOptions ho;
    ho.threads = a.render.threads;
    render::hillshade(grid, ho);
    t0.restart();
    for (int k = 0; k < a.frames; ++k) {
        ho.azimuth_deg = sun_of_frame(k, a.frames).azimuth_deg;
        ho.altitude_deg = sun_of_frame(k, a.frames).elevation_deg;
        render::hillshade(grid, ho);
    }
    const double hill_s = t0.seconds();

    const double n = a.frames;
    std::printf("DEM %dx%d (%zu texels), %s view %dx%d, %d frames, %d threads\n", dem.width, dem.height, texels,
                options.view == render::ViewKind::map ? "map" : "perspective", image.width, image.height, a.frames,
                thread_count(a.render.threads));
    std::string stages;  // what the visibility pass computed: "horizons", "log-SH", ...
    for (const auto& stage : scene.state().visibility_stages()) stages += (stages.empty() ? "" : ", ") + stage.label;
    const bool exact_terrain =
        scene.state().options().terrain_transfer == render::RendererOptions::TerrainTransfer::exact;
    std::printf("one-time: visibility (%s; exact horizons, %d directions) %.3f s + transfer vectors (%s) %.3f s "
                "(bounced light %.3f s of it, %d bounces; %zu specular, %zu water texels)\n",
                stages.c_str(), a.render.directions, scene.state().visibility_seconds(),
                exact_terrain ? "terrain projected from its horizons" : "log-SH", scene.state().transfer_seconds(),
                scene.state().bounce_seconds(), scene.state().options().bounce.bounces,
                scene.state().specular_index().size(), scene.state().water_index().size());
    std::printf("per frame: sky SH + sky table %.2f ms, sun visibility sweep %.2f ms, shading %.2f ms, "
                "total %.2f ms\n",
                sky_s / n * 1e3, sun_s / n * 1e3, shade_s / n * 1e3, frames_s / n * 1e3);
    std::printf("relight: %.1f Mpx/s (per-frame work after the visibility pass: sky SH, sun sweep, shading%s)\n",
                pixels * n / frames_s * 1e-6, options.view == render::ViewKind::map ? "" : ", view composition");
    std::printf("end-to-end with files: %.1f Mpx/s (%.2f ms per frame incl. tone mapping and PNG writing, on %d "
                "writer thread%s with a %d-frame queue; shading alone %.1f Mpx/s, %.2f ms); one after the other: "
                "%.1f Mpx/s (%.2f ms per frame); PNG %.1f KB per frame\n",
                pixels * n / files_s * 1e-6, files_s / n * 1e3, a.writer_threads, a.writer_threads == 1 ? "" : "s",
                a.write_queue, pixels * n / frames_s * 1e-6, frames_s / n * 1e3, pixels * n / files_serial_s * 1e-6,
                files_serial_s / n * 1e3, double(file_bytes) / n * 1e-3);
    // CPU time does not grow with other processes' load the way wall time does: the rate the
    // cores could sustain if they were this process's alone, and how busy it kept them.
    const int cores = thread_count(0);
    std::printf("CPU per frame: shading %.2f ms, with files %.2f ms; on %d idle core%s at most %.1f Mpx/s shading "
                "alone and %.1f Mpx/s with files (this run kept them %.0f%% and %.0f%% busy)\n",
                frames_cpu_s / n * 1e3, files_cpu_s / n * 1e3, cores, cores == 1 ? "" : "s",
                pixels * n * cores / frames_cpu_s * 1e-6, pixels * n * cores / files_cpu_s * 1e-6,
                100 * frames_cpu_s / (frames_s * cores), 100 * files_cpu_s / (files_s * cores));
    std::printf("writing one frame on one thread: auto exposure %.2f ms, tone mapping %.2f ms, PNG encoding and "
                "writing %.2f ms\n",
                exposure_ms, tone_ms, png_ms);
    std::printf("baseline hillshade (local, no shadows, no sky): %.1f Mpx/s\n", double(texels) * n / hill_s * 1e-6);
    std::printf("with the one-time cost over %d frames: %.1f Mpx/s\n", a.frames,
                pixels * n / (frames_s + setup_s) * 1e-6);
    std::printf("backend: %s\n", device.name().c_str());
    if (a.compare_unfused) compare_unfused(dem, options, a.frames, scene);
    if (a.compare_cpu) {
        if (device.on_vulkan()) compare_with_cpu(dem, options, a.frames, scene, setup_s);
        else std::printf("--compare-cpu: the run above was the CPU path already\n");
    }
    if (a.compare_devices) compare_devices(a, dem, exposure);
}

}  // namespace

void add_bench_relight_command(CLI::App& bench) {
    auto a = std::make_shared<BenchRelightArgs>();
    CLI::App* cmd = bench.add_subcommand(
        "relight", "Relighting throughput after the visibility pass (Mpx/s), end to end with files, and a hillshade "
                   "baseline in the same run");
    add_render_options(*cmd, a->render);
    cmd->add_option("--frames", a->frames, "Frames to time (sun over a day's arc)")->capture_default_str()->check(
        within(1, 100000));
    cmd->add_option("--keep", a->out_dir, "Keep the written frames in this directory (default: a temp dir, removed)");
    cmd->add_option("--write-queue", a->write_queue, "Frames that may wait for the PNG writer threads")
        ->capture_default_str()
        ->check(within(1, 64));
    cmd->add_option("--writer-threads", a->writer_threads, "Threads encoding and writing the PNG frames, as for relight")
        ->capture_default_str()
        ->check(within(1, 64));
    cmd->add_flag("--compare-unfused", a->compare_unfused,
                  "Also time the shading stage against the CPU RenderBackend's unfused one (as before the fused "
                  "CPU loop) in the same run, frames interleaved");
    cmd->add_flag("--compare-cpu", a->compare_cpu,
                  "Also time the CPU path (one-time stages and frames) in the same run and print device / cpu ratios");
    cmd->add_flag("--compare-devices", a->compare_devices,
                  "Also run the whole job (one-time stages, frames with PNG files) on the default path (--device "
                  "auto), --device cpu and --device vulkan in the same run, and print default / fastest");
    cmd->callback([a] { run_bench_relight(*a); });
}

}  // namespace ts::app
