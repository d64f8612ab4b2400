// `terrashade bench fly`: the flythrough's frame rate offscreen (the window's pipeline without
// presenting), along a fixed path over a DEM at 960x540: fps (mean), the 99th-percentile frame
// time, triangles per frame and the screen-space error bound of the LOD selection; and the same
// with a coarser LOD goal as a baseline for the ratio; with --mesh, the aircraft without and with
// its shadows, and a low chase (the aircraft 25 m above the ground) terrain-only and with it,
// for the shadows' cost against terrain-only in the same run. docs/flythrough.md records the figures.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "app/bench/bench_command.hpp"
#include "app/bench/error_stats.hpp"
#include "app/dem_input.hpp"
#include "app/job_memory.hpp"
#include "app/options/mesh_forward_option.hpp"
#include "core/blockers/sphere_cache.hpp"
#include "core/blockers/sphere_decomposition.hpp"
#include "core/dem/dem_source.hpp"
#include "core/fly/flight_path.hpp"
#include "core/fly/fly_camera.hpp"
#include "core/light/utc_time.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/util/error.hpp"
#include "core/util/stopwatch.hpp"
#include "gpu/context.hpp"
#include "gpu/fly/flythrough.hpp"

namespace ts::app {
namespace {

struct BenchFlyArgs {
    DemInput dem;
    std::string size = "960x540";
    int frames = 120;
    double pixel_error = 2.0;
    int directions = 16;
    std::string time = "2024-06-21T07:30:00Z";
    std::string mesh;  // an aircraft 60 m ahead of the camera: the run is repeated with it
    std::string mesh_forward = "auto";
    std::vector<int> spheres = {64, 400};  // the aircraft's shadows at each count (0: none)
    std::string sphere_cache_dir;
    // The first run again with the DEM streamed by tile within this budget (MB; 0: not run).
    double stream_budget_mb = 0;
    int overview_level = 0;
    double stream_speed_mps = 0;  // the streamed run's ground speed (0: the whole track)
};

struct Figures {
    double fps = 0, mean_ms = 0, p99_ms = 0, tris = 0, error_px = 0, error_max_px = 0, select_ms = 0;
    // Streamed: patches drawn coarser while their tile loaded (all frames), tiles resident at the end.
    std::size_t fallbacks = 0, tiles_resident = 0;
    double tiles_ms = 0;
};

// low: the aircraft 25 m above the ground along the same track and the camera chasing it (60 m
// behind, 15 m above), so its sky shadow's footprint (about 100 m across for a Cessna) fills
// the lower part of the frame: the shadows' worst case. Terrain-only runs of it keep the
// camera and draw no aircraft.
// speed_mps > 0: the same track at that ground speed, a frame every 1/30 s, from its start.
Figures fly_once(gpu::Flythrough& flight, int frames, bool with_aircraft, bool low, double speed_mps = 0) {
    // Across the DEM from its south-west quarter to its north-east, at 1.4x its top height
    // over the ground at the start, looking ahead and down a little.
    const auto& frame = flight.frame();
    double top = 0;
    for (float z : flight.scene().grid().z) top = std::max(top, double(z));
    const glm::dvec2 a = frame.to_metric(0.2 * (frame.width() - 1), 0.8 * (frame.height() - 1));
    const glm::dvec2 b = frame.to_metric(0.8 * (frame.width() - 1), 0.2 * (frame.height() - 1));
    const double track_m = glm::length(b - a);
    auto pose_at = [&](double f) {
        if (speed_mps > 0) f = std::min(1.0, f * (frames - 1) * speed_mps / 30.0 / track_m);
        const glm::dvec2 m = frame.to_metric((0.2 + 0.6 * f) * (frame.width() - 1), (0.8 - 0.6 * f) * (frame.height() - 1));
        fly::CameraPose p;
        p.eye = {m.x, m.y, std::max(top * 0.8, flight.ground_height_m({m.x, m.y, 0}) + 400.0)};
        p.heading_deg = 45.0 + 40.0 * std::sin(6.0 * f);
        p.pitch_deg = -10.0;
        return p;
    };
    std::vector<double> ms;
    std::vector<std::uint8_t> rgba;
    Figures fig;
    gpu::FlyFrameUniforms u;
    gpu::FlyFrameStats st;
    for (int i = -3; i < frames; ++i) {  // three warm-up frames
        const double f = double(std::max(i, 0)) / double(std::max(frames - 1, 1));
        const Stopwatch w;
        fly::CameraPose camera = pose_at(f);
        fly::CameraPose aircraft = camera;
        const fly::CameraAxes axes = fly::camera_axes(camera.heading_deg, camera.pitch_deg, 0.0);
        aircraft.eye += axes.forward * 60.0;
        aircraft.pitch_deg = 0.0;
        if (low) {
            aircraft.eye.z = flight.ground_height_m(aircraft.eye) + 25.0;
            camera = fly::chase_pose(aircraft);
        }
        flight.prepare(camera, u, st, with_aircraft ? &aircraft : nullptr);
        flight.renderer().render_to_memory(u, flight.patches(), rgba);
        if (i < 0) continue;
        ms.push_back(w.milliseconds());
        fig.tris += double(st.triangles);
        fig.error_px = std::max(fig.error_px, st.screen_error_px);
        fig.error_max_px = std::max(fig.error_max_px, st.screen_error_max_px);
        fig.select_ms += st.select_ms;
        fig.fallbacks += st.coarse_fallbacks;
        fig.tiles_resident = st.tiles_resident;
        fig.tiles_ms += st.tiles_ms;
    }
    double sum = 0;
    for (double v : ms) sum += v;
    fig.mean_ms = sum / double(ms.size());
    fig.fps = 1000.0 / fig.mean_ms;
    fig.p99_ms = bench::percentile(ms, 0.99);
    fig.tris /= double(frames);
    fig.select_ms /= double(frames);
    return fig;
}

void run_bench_fly(const BenchFlyArgs& a) {
    int w = 0, h = 0;
    char x = 0;
    if (std::sscanf(a.size.c_str(), "%d%c%d", &w, &x, &h) != 3 || w < 16 || h < 16)
        throw InputError("--size " + a.size + ": give WIDTHxHEIGHT");
    if (a.frames < 2) throw InputError("--frames must be >= 2");
    // A DEM too large to fly whole (fly --stream off would refuse it) runs streamed only.
    bool whole_fits = true;
    {
        const std::vector<std::filesystem::path> files(a.dem.files.begin(), a.dem.files.end());
        const dem::DemSource source(files);
        const std::uint64_t bytes = gpu::whole_fly_bytes(std::int64_t(source.layout().width) * source.layout().height);
        try {
            check_job_memory("flown whole", bytes, "");
        } catch (const InputError&) {
            whole_fits = false;
        }
        if (!whole_fits && !(a.stream_budget_mb > 0))
            throw InputError("bench fly: the DEM takes ~" + std::to_string(bytes >> 30) +
                             " GB flown whole, more than is available: give --stream-budget MB");
    }
    const dem::Dem dem = whole_fits ? load_dem_input(a.dem) : dem::Dem{};
    gpu::Context context;
    if (whole_fits)
        std::printf("bench fly: %s, %dx%d texels, %d frames at %dx%d on %s\n", a.dem.files.front().c_str(), dem.width,
                    dem.height, a.frames, w, h, context.device_info().name.c_str());
    else
        std::printf("bench fly: %s, %d frames at %dx%d on %s; too large to fly whole: streamed only\n",
                    a.dem.files.front().c_str(), a.frames, w, h, context.device_info().name.c_str());
    std::printf("lod_goal_px,lod_quantile,fps_mean,frame_ms_mean,frame_ms_p99,select_ms,triangles_per_frame,"
                "screen_error_px,screen_error_worst_texel_px\n");
    struct Run {
        double goal, quantile;
        bool aircraft;
        int spheres;  // its shadows' sphere count, 0: no shadows
        bool low = false;
    };
    // The goal at the default quantile, then every texel held to it (strict), then a 4x coarser
    // goal; with --mesh, the first again with the aircraft without shadows, then with its
    // shadows at each --spheres count.
    std::vector<Run> runs = {
        {a.pixel_error, 0.99, false, 0}, {a.pixel_error, 1.0, false, 0}, {4.0 * a.pixel_error, 0.99, false, 0}};
    if (!a.mesh.empty()) {
        runs.push_back({a.pixel_error, 0.99, true, 0});
        for (int n : a.spheres)
            if (n > 0) runs.push_back({a.pixel_error, 0.99, true, n});
        // The low chase: terrain-only, then with the aircraft and its shadows.
        runs.push_back({a.pixel_error, 0.99, false, 0, true});
        runs.push_back({a.pixel_error, 0.99, true, 0, true});
        for (int n : a.spheres)
            if (n > 0) runs.push_back({a.pixel_error, 0.99, true, n, true});
    }
    for (int n : a.spheres) {
        blockers::DecompositionOptions d;
        d.count = n;
        if (n != 0) blockers::validate(d);
    }
    const mesh::TriangleMesh aircraft_mesh = a.mesh.empty() ? mesh::TriangleMesh{} : mesh::import_mesh(a.mesh);
    const std::filesystem::path cache =
        a.sphere_cache_dir.empty() ? blockers::default_sphere_cache_dir() : std::filesystem::path(a.sphere_cache_dir);
    const double yaw = a.mesh.empty() ? 0.0 : mesh::forward_yaw_deg(mesh_forward_axis(a.mesh_forward, a.mesh));
    double whole_start_ms = 0;
    if (!whole_fits) runs.clear();
    for (const Run& run : runs) {
        const double goal = run.goal;
        gpu::FlySettings s;
        s.width = w, s.height = h;
        s.directions = a.directions;
        s.lod.pixel_error = goal;
        s.lod.error_quantile = run.quantile;
        const Stopwatch start;
        gpu::Flythrough flight(dem, s, context);
        flight.set_time(light::parse_utc_time(a.time));
        if (whole_start_ms == 0) whole_start_ms = start.milliseconds();
        std::vector<blockers::Sphere> spheres;
        if (run.aircraft && run.spheres > 0) {
            blockers::DecompositionOptions d;
            d.count = run.spheres;
            spheres = blockers::decompose_cached(aircraft_mesh, d, cache).spheres;
        }
        if (run.aircraft) flight.set_aircraft(aircraft_mesh, 1.0, yaw, spheres);
        if (goal == a.pixel_error && run.quantile < 1.0 && !run.aircraft && !run.low) {
            const double k_px = h / (2.0 * std::tan(0.5 * fly::Projection{s.fov_deg, w, h, 1.0}.vertical_fov_rad()));
            std::printf("level,vertex_spacing_texels,error_q99_m,error_max_m,range_m (goal %.2f px)\n", goal);
            for (int k = 0; k < flight.tree().levels(); ++k)
                std::printf("%d,%d,%.2f,%.2f,%.0f\n", k, 1 << k, flight.tree().level_error_m(k),
                            flight.tree().level_max_error_m(k), flight.tree().range_m(k, k_px));
        }
        const Figures f = fly_once(flight, a.frames, run.aircraft, run.low);
        const std::string label =
            std::string(run.low ? "low chase " : "") +
            (!run.aircraft ? "" : spheres.empty() ? "aircraft " : "aircraft+shadows(" + std::to_string(spheres.size()) + " spheres) ");
        std::printf("%s%.2f,%.2f,%.2f,%.2f,%.2f,%.3f,%.0f,%.3f,%.3f\n", label.c_str(), goal,
                    run.quantile, f.fps, f.mean_ms, f.p99_ms, f.select_ms, f.tris, f.error_px, f.error_max_px);
    }
    if (a.mesh.empty()) std::printf("with an aircraft: give --mesh FILE\n");
    if (a.stream_budget_mb > 0) {
        // The first run's flight over the DEM streamed by tile, tiles loaded on the worker as in
        // the window (frames do not wait: a tile not in yet is drawn coarser and counted).
        const std::vector<std::filesystem::path> files(a.dem.files.begin(), a.dem.files.end());
        const dem::DemSource source(files);
        gpu::FlySettings s;
        s.width = w, s.height = h;
        s.directions = a.directions;
        s.lod.pixel_error = a.pixel_error;
        s.memory_budget_bytes = std::size_t(a.stream_budget_mb * 1048576.0);
        s.overview_level = a.overview_level;
        const Stopwatch start;
        gpu::Flythrough flight(source, s, context);
        flight.set_time(light::parse_utc_time(a.time));
        const double start_ms = start.milliseconds();
        const Figures f = fly_once(flight, a.frames, false, false, a.stream_speed_mps);
        std::printf("streamed(overview level %d, %d tile slots, %.0f MB%s) %.2f,0.99,%.2f,%.2f,%.2f,%.3f,%.0f,%.3f,%.3f\n",
                    flight.overview()->level, flight.detail_tiles()->slots(), a.stream_budget_mb,
                    a.stream_speed_mps > 0 ? (", " + std::to_string(int(a.stream_speed_mps)) + " m/s").c_str() : "",
                    a.pixel_error, f.fps,
                    f.mean_ms, f.p99_ms, f.select_ms, f.tris, f.error_px, f.error_max_px);
        std::printf("start_ms_whole,start_ms_streamed,tiles_loaded,tiles_resident,coarse_fallbacks_all_frames,"
                    "tile_ms_per_frame,tile_bytes_resident_peak\n%.0f,%.0f,%llu,%zu,%zu,%.2f,%zu\n",
                    whole_start_ms, start_ms, static_cast<unsigned long long>(flight.detail_tiles()->loaded()),
                    f.tiles_resident, f.fallbacks, f.tiles_ms / a.frames, flight.detail_tiles()->peak_resident_bytes());
    }
}

}  // namespace

void add_bench_fly_command(CLI::App& bench) {
    auto a = std::make_shared<BenchFlyArgs>();
    CLI::App* cmd = bench.add_subcommand("fly", "flythrough frame rate offscreen: fps, p99 frame time, triangles, LOD error");
    add_dem_input_options(*cmd, a->dem);
    cmd->add_option("--size", a->size, "frame size")->capture_default_str();
    cmd->add_option("--frames", a->frames, "frames along the path")->capture_default_str();
    cmd->add_option("--pixel-error", a->pixel_error, "LOD goal (px); also run at 4x as the baseline")->capture_default_str();
    cmd->add_option("--directions", a->directions, "horizon azimuths of the visibility")->capture_default_str();
    cmd->add_option("--time", a->time, "UTC time of the sun")->capture_default_str();
    cmd->add_option("--mesh", a->mesh, "an aircraft mesh: the first run again with it 60 m ahead of the camera");
    add_mesh_forward_option(*cmd, a->mesh_forward);
    cmd->add_option("--spheres", a->spheres, "with --mesh: its shadows' sphere counts, one run each (0: none)")
        ->delimiter(',')
        ->capture_default_str();
    cmd->add_option("--sphere-cache-dir", a->sphere_cache_dir, "where sphere decompositions are cached");
    cmd->add_option("--stream-budget", a->stream_budget_mb,
                    "also fly the DEM streamed by tile within this many MB (fly --memory-budget)");
    cmd->add_option("--overview-level", a->overview_level, "with --stream-budget: fly --overview-level")
        ->capture_default_str();
    cmd->add_option("--stream-speed", a->stream_speed_mps,
                    "with --stream-budget: fly the track at this ground speed (m/s, 30 frames a second) instead "
                    "of across the whole DEM in --frames frames");
    cmd->callback([a] { run_bench_fly(*a); });
}

}  // namespace ts::app
