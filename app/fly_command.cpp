// `terrashade fly`: a flight over real terrain in a window (GLFW + Vulkan swapchain), or N
// frames of a flight path rendered offscreen with the same pipeline (--frames N --out DIR).
// This file parses the options and makes the flight; the window's loop (input, frames) is
// gpu/fly/fly_window_loop.hpp.
// docs/flythrough.md describes the LOD, the shading and the controls.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/dem_input.hpp"
#include "core/dem/dem_source.hpp"
#include "app/interrupt_watcher.hpp"
#include "app/io_plan.hpp"
#include "app/job_memory.hpp"
#include "app/options/colors_option.hpp"
#include "app/options/bounce_option.hpp"
#include "app/options/sky_light_option.hpp"
#include "app/options/directions_option.hpp"
#include "app/options/max_error_option.hpp"
#include "app/options/mesh_forward_option.hpp"
#include "app/options/quantity_flags.hpp"
#include "app/options/size_option.hpp"
#include "app/options/sky_option.hpp"
#include "app/options/sun_options.hpp"
#include "app/options/verbose_option.hpp"
#include "core/blockers/sphere_cache.hpp"
#include "core/blockers/sphere_decomposition.hpp"
#include "core/fly/hud_status.hpp"
#include "core/fly/hud_text.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/quality/radiance_quality.hpp"
#include "core/quality/visibility_quality.hpp"
#include "core/render/render_scene.hpp"
#include "core/visibility/visibility_grid.hpp"
#include "core/raster/png_writer.hpp"
#include "core/util/angles.hpp"
#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"
#include "core/util/progress_bar.hpp"
#include "core/util/temp_files.hpp"
#include "core/util/staged_outputs.hpp"
#include "core/util/stopwatch.hpp"
#include "gpu/context.hpp"
#include "gpu/fly/flythrough.hpp"
#include "gpu/fly/fly_window.hpp"
#include "gpu/fly/fly_window_loop.hpp"

namespace ts::app {
namespace {

constexpr const char* kKeys =
    "Keys (window):\n"
    "  Esc           quit (or close the window)\n"
    "  C             camera: chase -> cockpit -> free -> orbit\n"
    "  W/S A/D R/F   free flight: forward/back, left/right, up/down (Shift: x5)\n"
    "  mouse drag    look around (free), turn around the point (orbit)\n"
    "  arrows        turn (free) / orbit; Up/Down in orbit zoom\n"
    "  = / -         speed x1.5 / /1.5 (free flight)\n"
    "  Space         pause / resume the path\n"
    "  [ / ]         time of day -15 / +15 minutes;  , / .  -1 / +1 hour\n"
    "  P or F12      screenshot (PNG in --out, default the current directory)\n"
    "  K             start / stop recording the flight to --record (CSV, the --path format)\n"
    "  H             HUD in the frame on / off (--hud)\n"
    "  F1            print these keys\n";

struct FlyArgs {
    DemInput dem;
    std::string time = "2024-06-21T07:30:00Z";
    std::string sky = "clear";
    ColorsArgs colors;  // --colors, --snow-line
    std::string size = "960x540";
    std::string vsync = "on";
    std::string path;
    std::string mesh;
    double mesh_scale = 1.0;
    std::string mesh_forward = "auto";
    int spheres = 64;
    std::string sphere_cache_dir;
    bool no_aircraft_shadows = false;
    double min_solid_angle_sr = 0.01;
    double sky_detail = 0.05;
    std::string camera = "chase";
    std::string hud;  // on|off; empty: on in the window, off with --frames
    int frames = 0;  // 0: the window
    bool frames_given = false;
    bool verbose = false;
    int exit_after = 0;
    std::string out;
    std::string record = "fly_recording.csv";
    int directions = 16;
    render::BounceSettings bounce;
    SkyLightArgs sky_light;
    double pixel_error = 2.0;
    double lod_quantile = 0.99;
    int patch_quads = 16;
    double haze_km = 250.0;
    double fov_deg = 60.0;
    std::string shadow_detail = "pixel";
    // --max-error E[,PX]: the relative radiance error E chooses --directions, the screen-space
    // error PX (pixels) is the LOD's --pixel-error; the flags given explicitly, which conflict.
    std::string max_error;
    bool directions_given = false, pixel_error_given = false;
    // A DEM larger than the budget is streamed by tile (gpu/fly/flythrough.hpp).
    std::string stream = "auto";
    double memory_budget_mb = 4096;
    int overview_level = 0;
};

struct FlyErrorBounds {
    double radiance = 0;
    std::optional<double> pixels;
};

FlyErrorBounds parse_fly_max_error(const std::string& text) {
    FlyErrorBounds b;
    double px = 0;
    char rest = 0;
    const int n = std::sscanf(text.c_str(), "%lf,%lf%c", &b.radiance, &px, &rest);
    const bool one = n == 1 && text.find(',') == std::string::npos;
    if (!(one || n == 2))
        throw InputError("--max-error " + text + ": give E (relative radiance error) or E,PX (and screen-space pixels)");
    if (!(b.radiance > 0)) throw InputError("--max-error must be > 0 (a relative radiance error, e.g. 0.05 for 5%)");
    if (n == 2) {
        if (!(px > 0.05 && px <= 100)) throw InputError("--max-error " + text + ": the screen-space error PX in (0.05, 100]");
        b.pixels = px;
    }
    return b;
}

fly::CameraMode parse_camera_mode(const std::string& s) {
    if (s == "chase") return fly::CameraMode::chase;
    if (s == "cockpit") return fly::CameraMode::cockpit;
    if (s == "free") return fly::CameraMode::free;
    if (s == "orbit") return fly::CameraMode::orbit;
    throw InputError("--camera " + s + ": give chase, cockpit, free or orbit");
}

// The flight when no --path is given: straight over the DEM from the default start, 80 m/s,
// 20 s.
fly::FlightPath default_path(const gpu::Flythrough& s) {
    const fly::CameraPose start = s.default_pose();
    std::vector<fly::FlightPose> poses;
    const double h = radians(start.heading_deg);
    for (int i = 0; i <= 4; ++i) {
        const double t = 5.0 * i;
        const glm::dvec3 eye = start.eye + glm::dvec3(std::sin(h), std::cos(h), 0.0) * (80.0 * t);
        fly::CameraPose p = start;
        p.eye = eye;
        p.pitch_deg = 0.0;
        poses.push_back(s.flight_pose_of(p, t));
    }
    return fly::FlightPath(std::move(poses));
}

bool parse_hud(const std::string& text, bool offscreen) {
    if (text.empty()) return !offscreen;
    if (text == "on") return true;
    if (text == "off") return false;
    throw InputError("--hud " + text + ": give on or off");
}

// One flight's frames per folder: frame_NNNN.png of another flight (another count or size) beside
// this one's, under a frames.csv that lists only this one's, would be a mixed series. Refused
// before any work; the user's other files (and window screenshots) may stay.
void refuse_another_flight(const std::string& out) {
    std::error_code ec;
    if (!std::filesystem::is_directory(out, ec)) return;
    for (const auto& e : std::filesystem::directory_iterator(out, ec)) {
        const std::string name = e.path().filename().string();
        if (name == "frames.csv" || (name.starts_with("frame_") && name.ends_with(".png")))
            throw input_error(out, "holds the frames of another flight (" + name +
                                       "); remove them (frame_*.png, frames.csv) or write elsewhere");
    }
}

void run_frames(const FlyArgs& a, gpu::Flythrough& flight, const fly::FlightPath& path, fly::CameraMode mode) {
    std::error_code ec;
    if (!std::filesystem::exists(a.out, ec)) {
        // Known to the interrupt before it exists: one before the first frame leaves no empty folder.
        temp_files::track_created_directory(a.out);
        std::filesystem::create_directories(a.out);
    }
    interrupt::report_progress("frames", std::uint64_t(a.frames));
    gpu::FlyFrameUniforms u;
    gpu::FlyFrameStats st;
    std::vector<std::uint8_t> rgba;
    double worst_error = 0, frame_ms_sum = 0;
    std::size_t tris_sum = 0;
    ProgressBar bar("frames", std::uint64_t(a.frames), "frames");
    const std::string header = "frame,t_s,patches,triangles,screen_error_px,screen_error_max_px,select_ms,draw_ms,"
                               "coarse_fallbacks,tiles_resident,tiles_loaded,tiles_ms\n";
    std::string csv = header;
    // An interrupt leaves frames.csv listing exactly the frames on disk.
    interrupt::InterruptIndex& index =
        interrupt::index_on_interrupt((std::filesystem::path(a.out) / "frames.csv").string(), header, std::size_t(a.frames));
    const bool hud = parse_hud(a.hud, true);
    double previous_draw_ms = 0;
    for (int i = 0; i < a.frames; ++i) {
        const double t = path.start_s() + (a.frames > 1 ? path.duration_s() * i / (a.frames - 1) : 0.0);
        const fly::CameraPose aircraft = flight.pose_of(path.at(t));
        const fly::CameraPose camera = gpu::camera_for(mode, aircraft);
        flight.prepare(camera, u, st, mode == fly::CameraMode::cockpit ? nullptr : &aircraft);
        // The draw time shown is the previous frame's: this one's is known only after it.
        if (hud)
            gpu::show_hud(flight.renderer(),
                          gpu::hud_status(flight, "frame " + std::to_string(i + 1) + "/" + std::to_string(a.frames),
                                          st, st.select_ms + previous_draw_ms, previous_draw_ms, camera, flight.time(),
                                          mode, false, false));
        const Stopwatch draw;
        flight.renderer().render_to_memory(u, flight.patches(), rgba);
        const double draw_ms = draw.milliseconds();
        previous_draw_ms = draw_ms;
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", i);
        char line[256];
        std::snprintf(line, sizeof line, "%d,%.3f,%zu,%zu,%.3f,%.3f,%.3f,%.3f,%zu,%zu,%zu,%.1f\n", i, t, st.patches,
                      st.triangles, st.screen_error_px, st.screen_error_max_px, st.select_ms, draw_ms, st.coarse_fallbacks,
                      st.tiles_resident, st.tiles_loaded, st.tiles_ms);
        const std::filesystem::path frame = std::filesystem::path(a.out) / name;
        index.set(std::size_t(i), frame.string(), line);
        gpu::write_rgba_png(frame, flight.renderer().width(), flight.renderer().height(), rgba);
        csv += line;
        worst_error = std::max(worst_error, st.screen_error_px);
        frame_ms_sum += draw_ms + st.select_ms;
        tris_sum += st.triangles;
        bar.advance();
    }
    bar.finish();
    write_atomically(std::filesystem::path(a.out) / "frames.csv", [&](const std::filesystem::path& tmp) {
        std::ofstream(tmp) << csv;
    });
    index.forget();
    std::printf("wrote %d frames (%dx%d) to %s: %.1f ms and %zu triangles a frame on average, screen-space error <= %.2f px\n",
                a.frames, flight.renderer().width(), flight.renderer().height(), a.out.c_str(),
                frame_ms_sum / std::max(1, a.frames), tris_sum / std::size_t(std::max(1, a.frames)), worst_error);
}

// Flown whole, a DEM's shading state is held at once (gpu::whole_fly_bytes): refused before it
// is read when the machine cannot hold it, since what does not fit is an OOM kill after minutes
// of shading, not a clean error.
void check_whole_fly_memory(int width, int height) {
    check_job_memory("fly of " + std::to_string(width) + "x" + std::to_string(height) + " texels flown whole",
                     gpu::whole_fly_bytes(std::int64_t(width) * height),
                     "stream it by tile (--stream auto or on, within --memory-budget) or --crop a smaller window");
}

// A pose under the terrain would put the camera inside it (a frame of garbage): refused, naming
// the pose and how far below it is.
void refuse_poses_below_terrain(const gpu::Flythrough& flight, const fly::FlightPath& path, const std::string& file) {
    const auto& poses = path.poses();
    for (std::size_t k = 0; k < poses.size(); ++k) {
        const double ground = flight.ground_height_m(flight.pose_of(poses[k]).eye);
        if (poses[k].height_m < ground) {
            char line[256];
            std::snprintf(line, sizeof line,
                          "--path %s: pose %zu (t_s %g) is %.1f m below the terrain (height %.1f m, ground %.1f m)",
                          file.c_str(), k + 1, poses[k].t_s, ground - poses[k].height_m, poses[k].height_m, ground);
            throw InputError(line);
        }
    }
}

void run_fly(const FlyArgs& a) {
    gpu::FlySettings settings;
    parse_size(a.size, SizeRange{16, 8192, "960x540"}, settings.width, settings.height);
    if (a.vsync != "on" && a.vsync != "off") throw InputError("--vsync " + a.vsync + ": give on or off");
    const fly::CameraMode mode = parse_camera_mode(a.camera);
    const light::UtcTime time = light::parse_utc_time(a.time);
    light::parse_sky_options(a.sky);
    settings.colors = color_design(a.colors);
    if (a.frames_given && a.frames < 1)
        throw InputError("--frames " + std::to_string(a.frames) + ": a count of frames, >= 1 (without --frames: the window)");
    if (a.exit_after < 0) throw InputError("--exit-after must be >= 0");
    const bool offscreen = a.frames > 0;
    if (offscreen && a.out.empty()) throw InputError("fly: --frames N needs --out DIR");
    parse_hud(a.hud, offscreen);
    if (!(a.pixel_error > 0.05 && a.pixel_error <= 100)) throw InputError("--pixel-error must be in (0.05, 100]");
    if (a.patch_quads < 4 || a.patch_quads > 128 || (a.patch_quads & (a.patch_quads - 1)) != 0)
        throw InputError("--patch-quads must be a power of two in [4, 128]");
    if (!(a.lod_quantile >= 0.5 && a.lod_quantile <= 1.0)) throw InputError("--lod-quantile must be in [0.5, 1]");
    if (!(a.fov_deg > 5 && a.fov_deg < 150)) throw InputError("--fov must be in (5, 150) degrees");
    std::optional<FlyErrorBounds> bounds;
    if (!a.max_error.empty()) {
        bounds = parse_fly_max_error(a.max_error);
        if (a.directions_given) throw InputError("--max-error chooses --directions itself; drop one of them");
        if (bounds->pixels && a.pixel_error_given)
            throw InputError("--max-error E,PX sets --pixel-error to PX; drop one of them");
    }
    if (!(a.haze_km >= 0)) throw InputError("--haze-km must be >= 0");
    if (!(a.mesh_scale > 0)) throw InputError("--mesh-scale must be > 0");
    const double forward_yaw = a.mesh.empty() ? 0.0 : mesh::forward_yaw_deg(mesh_forward_axis(a.mesh_forward, a.mesh));
    blockers::DecompositionOptions decomposition;
    decomposition.count = a.spheres;
    try {
        blockers::validate(decomposition);
    } catch (const QuantityError& e) {
        throw InputError(flag_message(e, "fly"));
    }
    if (!(a.min_solid_angle_sr > 0 && a.min_solid_angle_sr < 2.0 * kPi))
        throw InputError("--blocker-min-solid-angle must be in (0, 2 pi) steradians");
    if (!(a.sky_detail >= 0 && a.sky_detail <= 1)) throw InputError("--aircraft-sky-detail must be in [0, 1]");
    if (a.stream != "auto" && a.stream != "on" && a.stream != "off") throw InputError("--stream " + a.stream + ": give auto, on or off");
    if (!(a.memory_budget_mb >= 64 && a.memory_budget_mb <= 1e7)) throw InputError("--memory-budget must be in [64, 1e7] MB");
    if (a.overview_level < 0 || a.overview_level > 12) throw InputError("--overview-level must be in [0, 12] (0: from the budget)");
    IoPlan plan;
    plan.inputs("DEM", a.dem.files);
    plan.input("--path", a.path);
    plan.input("--mesh", a.mesh);
    plan.input("--sky", light::parse_sky_options(a.sky).hdr_path);
    plan_colors_input(plan, a.colors);
    if (offscreen) plan.output_directory("--out", a.out);
    plan.check();
    if (offscreen) refuse_another_flight(a.out);

    // The window is the first thing to fail without a display: before any heavy work. The
    // context is made after it (it needs the window's extensions) but must outlive it.
    std::unique_ptr<gpu::Context> context;
    std::unique_ptr<gpu::FlyWindow> window;
    gpu::ContextOptions context_options;
    if (!offscreen) {
        std::string reason;
        if (!gpu::display_available(reason))
            throw InputError("fly: " + reason + "; render offscreen with --frames N --out DIR");
        window = std::make_unique<gpu::FlyWindow>(settings.width, settings.height, "terrashade fly");
        context_options.instance_extensions = gpu::FlyWindow::instance_extensions();
        context_options.device_extensions = gpu::FlyWindow::device_extensions();
    }
    // A bad mesh file is found before the shading state is computed.
    if (!a.mesh.empty()) mesh::import_mesh(a.mesh);
    const std::optional<fly::FlightPath> given_path =
        a.path.empty() ? std::nullopt : std::optional<fly::FlightPath>(fly::read_flight_path(a.path));

    settings.sky = a.sky;
    settings.directions = a.directions;
    settings.bounce = a.bounce;
    check_bounce_options(settings.bounce);  // before any heavy work
    settings.sky_light = sky_light_settings(a.sky_light);
    settings.lod.pixel_error = a.pixel_error;
    settings.lod.patch_quads = a.patch_quads;
    settings.lod.error_quantile = a.lod_quantile;
    settings.haze_km = a.haze_km;
    settings.pixel_sun_shadows = a.shadow_detail == "pixel";
    settings.fov_deg = a.fov_deg;
    settings.aircraft_shadows = !a.no_aircraft_shadows;
    settings.aircraft_min_solid_angle_sr = a.min_solid_angle_sr;
    settings.aircraft_sky_detail = a.sky_detail;
    settings.memory_budget_bytes = std::size_t(a.memory_budget_mb * 1048576.0);
    settings.overview_level = a.overview_level;
    settings.wait_for_tiles = offscreen;
    // Headers only: whether the DEM fits is known before anything is decoded.
    std::unique_ptr<dem::DemSource> source;
    {
        std::vector<std::filesystem::path> files(a.dem.files.begin(), a.dem.files.end());
        auto opened = std::make_unique<dem::DemSource>(files);
        const std::int64_t texels = std::int64_t(opened->layout().width) * opened->layout().height;
        const bool big = gpu::whole_fly_bytes(texels) > settings.memory_budget_bytes;
        if (a.stream == "on" || (a.stream == "auto" && big)) {
            if (!a.dem.crop.empty()) throw InputError("--crop: a streamed DEM is flown whole; crop it beforehand or give --stream off");
            if (!a.dem.fill_voids) throw InputError("--no-fill: a streamed DEM's voids take the overview's heights; drop --no-fill");
            if (bounds)
                throw InputError("--max-error: not available on a streamed DEM (its roughness would take a pass of its own); "
                                 "give --directions and --pixel-error");
            source = std::move(opened);
            std::printf("streaming %s (%dx%d texels, ~%.0f MB whole) by tile within --memory-budget %.0f MB\n",
                        source->layout().source.c_str(), source->layout().width, source->layout().height,
                        double(gpu::whole_fly_bytes(texels)) / 1048576.0, a.memory_budget_mb);
            std::fflush(stdout);
        } else {
            // From the header; a crop is checked once read, by its own size.
            if (a.dem.crop.empty()) check_whole_fly_memory(opened->layout().width, opened->layout().height);
            if (a.stream == "off" && big)
                std::printf("warning: the DEM takes ~%.0f MB flown whole, over --memory-budget %.0f MB (--stream off)\n",
                            double(gpu::whole_fly_bytes(texels)) / 1048576.0, a.memory_budget_mb);
        }
    }
    dem::Dem dem = source ? dem::Dem{} : load_dem_input(a.dem);
    // The mesh needs a height everywhere: what is outside the terrain (a nodata collar, holes
    // too wide to fill, every void with --no-fill) is drawn as a floor at the lowest height.
    if (!source) dem::floor_outside(dem);
    if (!source && !a.dem.crop.empty()) check_whole_fly_memory(dem.width, dem.height);
    if (!source && (dem.width < 2 || dem.height < 2)) throw InputError("fly: the DEM needs at least 2x2 texels");
    if (bounds) {
        quality::RadianceScene scene;
        scene.roughness = quality::mean_tan_slope(visibility::VisibilityGrid(dem).view());
        scene.sun_elevations_deg = {render::sun_at_dem_centre(dem, time).elevation_deg};
        scene.exact_sun_available = false;  // fly's sun shadows are the sweep's
        const quality::RadianceChoice c = quality::choose_radiance(bounds->radiance, scene);
        settings.directions = c.directions;
        if (bounds->pixels) settings.lod.pixel_error = *bounds->pixels;
        std::printf("%s; screen-space error: --pixel-error %g px at the %g quantile of texels%s\n",
                    max_error_line(c.reason).c_str(),
                    settings.lod.pixel_error, settings.lod.error_quantile,
                    bounds->pixels ? "" : " (give --max-error E,PX to bound it)");
        std::fflush(stdout);
    }
    context = std::make_unique<gpu::Context>(context_options);
    std::unique_ptr<gpu::Flythrough> flight_owner = source ? std::make_unique<gpu::Flythrough>(*source, settings, *context)
                                                           : std::make_unique<gpu::Flythrough>(dem, settings, *context);
    gpu::Flythrough& flight = *flight_owner;
    const fly::FlightPath path = given_path ? *given_path : default_path(flight);
    if (given_path) refuse_poses_below_terrain(flight, *given_path, a.path);
    if (!a.mesh.empty()) {
        const mesh::TriangleMesh aircraft = mesh::import_mesh(a.mesh);
        std::vector<blockers::Sphere> spheres;
        if (settings.aircraft_shadows) {
            const std::filesystem::path cache = a.sphere_cache_dir.empty() ? blockers::default_sphere_cache_dir()
                                                                           : std::filesystem::path(a.sphere_cache_dir);
            const blockers::SphereDecomposition d = blockers::decompose_cached(aircraft, decomposition, cache);
            spheres = d.spheres;
            std::printf("aircraft %s: %zu triangles, %zu spheres (%s)\n", a.mesh.c_str(), aircraft.triangle_count(),
                        spheres.size(), d.cached ? "cached" : "decomposed now");
        }
        if (a.verbose) std::printf("aircraft %s: %s\n", a.mesh.c_str(), describe_mesh_forward(a.mesh_forward, a.mesh).c_str());
        flight.set_aircraft(aircraft, a.mesh_scale, forward_yaw, spheres);
    }
    const double relight_ms = flight.set_time(time);
    std::printf("sun: azimuth %.2f deg, elevation %.2f deg at %s (relight %.0f ms); %d LOD levels, on %s\n",
                flight.sun().azimuth_deg, flight.sun().elevation_deg, light::format_utc_time(time).c_str(),
                relight_ms, flight.tree().levels(), flight.context().device_info().name.c_str());
    if (offscreen) {
        run_frames(a, flight, path, mode);
    } else {
        window->attach(flight.context(), a.vsync == "on");
        gpu::FlyWindowLoop loop;
        loop.keys_help = kKeys;
        loop.shot_dir = a.out.empty() ? "." : a.out;
        loop.record = a.record;
        loop.hud = parse_hud(a.hud, false);
        loop.exit_after = a.exit_after;
        gpu::run_window(loop, flight, *window, path, mode, time);
        window.reset();
    }
    // TERRASHADE_VALIDATION=1: what the validation layer reported (the tests want none).
    for (const auto& m : context->validation_messages()) std::fprintf(stderr, "terrashade: validation: %s\n", m.c_str());
}

}  // namespace

void add_fly_command(CLI::App& root) {
    auto args = std::make_shared<FlyArgs>();
    CLI::App* cmd = root.add_subcommand("fly", "fly over the terrain in a window (Vulkan), or render a path's frames offscreen");
    cmd->footer(kKeys);
    add_dem_input_options(*cmd, args->dem);
    add_time_option(*cmd, args->time);  // [ and ] change it in the window
    cmd->get_option("--time")->capture_default_str();
    add_sky_option(*cmd, args->sky);
    add_colors_options(*cmd, args->colors);
    cmd->add_option("--size", args->size, "window or frame size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--vsync", args->vsync, "on: present at the display's rate; off: as fast as it renders")
        ->capture_default_str();
    cmd->add_option("--path", args->path,
                    "flight path CSV: t_s,lon,lat,height_m,heading_deg,pitch_deg,roll_deg (default: straight over the DEM)");
    cmd->add_option("--mesh", args->mesh, "aircraft mesh drawn along the path (AC3D, glTF, OBJ, ...)");
    cmd->add_option("--mesh-scale", args->mesh_scale, "scale of the aircraft mesh")->capture_default_str();
    add_mesh_forward_option(*cmd, args->mesh_forward);
    cmd->add_option("--spheres", args->spheres,
                    "bounding spheres of the aircraft that cast its shadows, 8..512 (cached on disk)")
        ->capture_default_str();
    cmd->add_option("--sphere-cache-dir", args->sphere_cache_dir,
                    "where sphere decompositions are cached (default $XDG_CACHE_HOME/terrashade/spheres)");
    cmd->add_flag("--no-aircraft-shadows", args->no_aircraft_shadows,
                  "the aircraft casts no shadow on the terrain nor on itself");
    cmd->add_option("--blocker-min-solid-angle", args->min_solid_angle_sr,
                    "the aircraft darkens the terrain's sky only where its spheres' bound subtends more than this (sr)")
        ->capture_default_str();
    cmd->add_option("--aircraft-sky-detail", args->sky_detail,
                    "where the spheres' bound hides more of a receiver's sky than this fraction, its spheres count one "
                    "by one (0: everywhere); farther, the bound's cover scaled once")
        ->capture_default_str();
    cmd->add_option("--camera", args->camera, "chase, cockpit, free or orbit (C cycles them)")->capture_default_str();
    cmd->add_option("--hud", args->hud,
                    "on|off: the HUD (fps, timings, position, sun, camera) drawn in the frame's top-left corner "
                    "(default on in the window, H toggles it; off with --frames)");
    cmd->add_option("--frames", args->frames, "render N >= 1 frames of the path offscreen instead of a window (needs --out)")
        ->each([a = args.get()](const std::string&) { a->frames_given = true; });
    cmd->add_option("--exit-after", args->exit_after, "close the window after N frames (scripts and tests; 0 = never)");
    cmd->add_option("-o,--out", args->out, "directory for --frames (frame_NNNN.png, frames.csv) and screenshots");
    cmd->add_option("--record", args->record, "where K writes the recorded flight (CSV)")->capture_default_str();
    add_directions_option(*cmd, args->directions, &args->directions_given);  // once per DEM
    add_bounce_options(*cmd, args->bounce);
    add_sky_light_options(*cmd, args->sky_light);
    cmd->add_option("--pixel-error", args->pixel_error, "terrain LOD: screen-space geometric error goal in pixels")
        ->capture_default_str()
        ->each([a = args.get()](const std::string&) { a->pixel_error_given = true; });
    cmd->add_option("--max-error", args->max_error,
                    "adaptive quality E[,PX]: --directions the cheapest predicted to keep the relative radiance error "
                    "under E for this terrain and sun (e.g. 0.05), and PX the screen-space error in pixels "
                    "(--pixel-error; docs/accuracy.md)");
    cmd->add_option("--lod-quantile", args->lod_quantile,
                    "terrain LOD: which quantile of the per-texel mesh errors meets --pixel-error (1 = every texel)")
        ->capture_default_str();
    cmd->add_option("--patch-quads", args->patch_quads, "terrain LOD: quads per patch side (power of two)")
        ->capture_default_str();
    cmd->add_option("--haze-km", args->haze_km, "aerial perspective: distance of 1/e transmittance (0 = none)")
        ->capture_default_str();
    cmd->add_option("--fov", args->fov_deg, "horizontal field of view in degrees")->capture_default_str();
    cmd->add_option("--shadow-detail", args->shadow_detail,
                    "sun shadows' edges placed inside texels where each fragment's interpolated horizon crosses the "
                    "sun (pixel), or the texels' visible shares blended (texel: a texel-wide ramp along the texel lines)")
        ->capture_default_str()
        ->check(CLI::IsMember({"pixel", "texel"}));
    cmd->add_option("--stream", args->stream,
                    "auto: stream the DEM by tile when flying it whole would take more than --memory-budget; on; off")
        ->capture_default_str();
    cmd->add_option("--memory-budget", args->memory_budget_mb,
                    "MB a streamed DEM's overview, far field and detail tiles may hold in all")
        ->capture_default_str();
    cmd->add_option("--overview-level", args->overview_level,
                    "streamed DEMs: the overview keeps every 2^L-th texel (0: the finest that fits a quarter of the budget)")
        ->capture_default_str();
    add_verbose_flag(*cmd, args->verbose);
    cmd->callback([args] { run_fly(*args); });
}

}  // namespace ts::app
