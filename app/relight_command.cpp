// `terrashade relight`: the same DEM under the sun and sky of many instants. Visibility and
// transfer vectors are computed once; each frame is only the sky's SH, the sun's visibility
// sweep and the per-texel shading (docs/rendering.md, "Relighting").
#include <deque>
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
#include "app/compute_device.hpp"
#include "app/job_memory.hpp"
#include "app/interrupt_watcher.hpp"
#include "app/io_plan.hpp"
#include "app/render_options.hpp"
#include "app/shard_option.hpp"
#include "core/fly/flight_path.hpp"
#include "core/render/background_writer.hpp"
#include "core/render/frame_folder.hpp"
#include "core/render/sequence_exposure.hpp"
#include "core/light/time_interval.hpp"
#include "core/light/utc_time.hpp"
#include "core/util/shard_marker.hpp"
#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"
#include "core/util/progress_bar.hpp"
#include "core/util/stopwatch.hpp"
#include "core/util/temp_files.hpp"
#include "app/options/night_option.hpp"
#include "app/options/within_range.hpp"

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
    // --exposure-boost: how many EV automatic exposure may brighten a frame beyond the highest sun's.
    std::optional<double> exposure_boost_ev;
    NightArgs night;  // --night skip|include (app/options/night_option.hpp)
    bool overwrite = false;  // replace the series already in out_dir
    std::string shard;  // K/N
    std::string mesh_path;  // the first --mesh follows this flight path (CSV, core/fly/flight_path.hpp)
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

// The instant in a file name: 2026-06-21T0700Z (seconds only when not zero; no colons, which
// some file systems refuse).
std::string instant_for_file_name(light::UtcTime t) {
    std::string s;
    for (char c : light::format_utc_time(t))
        if (c != ':') s += c;
    if (s.size() == 18 && s.compare(15, 3, "00Z") == 0) s.replace(15, 3, "Z");  // YYYY-MM-DDTHHMM00Z
    return s;
}

struct Frame {
    light::UtcTime time;
    render::SunState sun;
    std::string file;
    double ev100 = 0;
    std::size_t index = 0;  // in the whole series (a shard has a part of it)
    double offset_s = 0;    // seconds from the series' first instant (where --mesh-path's t_s starts)
};

// --mesh-path: the first --mesh's pose at a frame, from the path's pose `offset_s` after its
// first sample (held at the ends), its scale kept.
mesh::Placement pose_on_path(const fly::FlightPath& path, double offset_s, const mesh::Placement& start) {
    const fly::FlightPose p = path.at(path.start_s() + offset_s);
    mesh::Placement m = start;
    m.lon_deg = p.lon_deg, m.lat_deg = p.lat_deg, m.height_m = p.height_m, m.above_ground = false;
    m.heading_deg = p.heading_deg, m.pitch_deg = p.pitch_deg, m.roll_deg = p.roll_deg;
    return m;
}

// The moving mesh's per-frame cost, for the closing line.
struct MeshMotion {
    double seconds = 0;
    long long texels = 0;
    std::size_t moves = 0;
};

constexpr const char* kTimesHeader = "frame,file,time_utc,sun_azimuth_deg,sun_elevation_deg,ev100\n";

std::string times_csv_row(const Frame& fr, bool linear) {
    char row[256];
    std::snprintf(row, sizeof row, "%zu,%s,%s,%.4f,%.4f,", fr.index, fr.file.c_str(),
                  light::format_utc_time(fr.time).c_str(), fr.sun.azimuth_deg, fr.sun.elevation_deg);
    std::string s = row;
    if (!linear) {  // EXR frames are linear: no exposure applied
        std::snprintf(row, sizeof row, "%.3f", fr.ev100);
        s += row;
    }
    return s + "\n";
}

void write_times_csv(const std::filesystem::path& path, const std::vector<Frame>& frames, bool linear) {
    write_atomically(path, [&](const std::filesystem::path& tmp) {
        std::FILE* f = std::fopen(tmp.c_str(), "w");
        if (!f) throw input_error(path.string(), "cannot write");
        std::fputs(kTimesHeader, f);
        for (const Frame& fr : frames) std::fputs(times_csv_row(fr, linear).c_str(), f);
        if (std::fclose(f) != 0) throw input_error(path.string(), "cannot write (disk full?)");
    });
}

void run_relight(const RelightArgs& a) {
    if (a.times.empty() == a.times_file.empty()) throw InputError("relight: give either --times or --times-file");
    const bool skip_night = skips_night(a.night);
    RenderArgs render_args = a.render;
    fly::FlightPath path;
    if (!a.mesh_path.empty()) {
        MeshArgs& m = render_args.meshes;
        if (m.files.empty()) throw InputError("--mesh-path moves the first --mesh: give one");
        if (m.at.size() + 1 != m.files.size())
            throw InputError("--mesh-path: the first --mesh follows the path, so give --at only for the other meshes (" +
                             std::to_string(m.files.size() - 1) + "), got " + std::to_string(m.at.size()));
        std::error_code ec;
        if (!std::filesystem::is_regular_file(a.mesh_path, ec)) throw input_error(a.mesh_path, "--mesh-path: no such file");
        path = fly::read_flight_path(a.mesh_path);
        if (path.empty()) throw input_error(a.mesh_path, "--mesh-path: no poses in the file");
        // The first pose stands in for the first mesh's --at: every check of a placement applies.
        const fly::FlightPose p0 = path.poses().front();
        char at[128];
        std::snprintf(at, sizeof at, "%.9f,%.9f,%.6f", p0.lon_deg, p0.lat_deg, p0.height_m);
        m.at.insert(m.at.begin(), at);
    }
    render::SceneOptions options = scene_options(render_args);
    if (!path.empty() && options.view == render::ViewKind::perspective)
        throw InputError("--mesh-path: a moving mesh is drawn in map and extent views only (--view map or an extent)");
    const render::Exposure exposure = exposure_of(render_args);
    IoPlan plan;
    plan_render_inputs(plan, render_args, options);
    plan.input("--times-file", a.times_file).input("--mesh-path", a.mesh_path).output_directory("--out", a.out_dir);
    plan.check();
    const Shard shard = shard_of_process(a.shard);
    if (a.exposure_boost_ev && (!exposure.automatic || a.format == "exr"))
        throw InputError("--exposure-boost: only with automatic exposure (not with --exposure EV or --format exr)");
    if (!shard.whole() && exposure.automatic && a.format != "exr")
        throw InputError("relight --shard: automatic exposure is averaged over neighbouring frames of the whole series; "
                         "give --exposure EV (or --format exr) so that shards match one run");
    const std::vector<light::UtcTime> times =
        a.times.empty() ? read_times_file(a.times_file) : light::parse_time_interval(a.times, 10000);
    const dem::Dem dem = load_dem_input(a.render.dem);
    warn_if_single_line(dem);
    // Every pose of the path on the DEM, before the meshes are read (a sample off it: exit 2 now).
    for (const fly::FlightPose& p : path.poses()) {
        mesh::Placement on;
        on.lon_deg = p.lon_deg, on.lat_deg = p.lat_deg;
        char where[64];
        std::snprintf(where, sizeof where, " (t_s %g)", p.t_s);
        render::mesh_anchor(dem.georef, on, a.mesh_path + where);
    }
    attach_meshes(render_args, dem, options);
    if (render_args.max_error) {
        // Every frame of the series (all shards choose alike): the prediction is the worst sun's.
        std::vector<render::SunState> suns;
        const render::SunSite sun_place = render::sun_site(dem);
        const double grid_north = dem.georef.grid_azimuth_of_north_deg();
        for (const auto& t : times)
            if (const render::SunState s = render::sun_at(sun_place, t); !skip_night || s.elevation_deg >= kNightElevationDeg)
                suns.push_back(render::sun_on_grid(s, grid_north));
        apply_max_error(render_args, dem, suns, options);
    }
    const int directions = options.renderer.directions;
    check_job_memory("relight of " + std::to_string(dem.width) + "x" + std::to_string(dem.height) + " texels",
                     render_peak_bytes(std::uint64_t(dem.width) * dem.height, directions, !options.meshes.empty()),
                     "use --crop, or fewer --directions (4 bytes per texel each)");
    // One series per folder: a folder that is not empty is refused here, or (--overwrite) its old
    // series removed, but only once the new one is about to be written (claim_folder, after the
    // visibility): an error or an interrupt before then leaves the folder as it was. A folder
    // made then is known to the interrupt before it exists (else a signal between the two would
    // leave it empty).
    render::check_frame_folder(a.out_dir, a.overwrite);
    const auto claim_folder = [&] {
        std::error_code ec;
        if (!std::filesystem::exists(a.out_dir, ec)) temp_files::track_created_directory(a.out_dir);
        render::claim_frame_folder(a.out_dir, a.overwrite);
    };
    // The sun of every instant first: night frames are known (and skipped) before any work.
    const render::SunSite site = render::sun_site(dem);
    std::vector<Frame> frames;
    std::size_t down = 0, night = 0;
    for (const auto& t : times) {
        const render::SunState sun = render::sun_at(site, t);
        if (sun.elevation_deg < kNightElevationDeg) ++night;
        if (sun.elevation_deg < -0.27) ++down;
        if (skip_night && sun.elevation_deg < kNightElevationDeg) continue;
        frames.push_back({t, sun, "", 0, 0,
                          std::chrono::duration<double>(t - times.front()).count()});
    }
    if (frames.empty())
        throw InputError("relight: the sun is below " + std::to_string(int(kNightElevationDeg)) +
                         " degrees (night) at every instant: nothing to render (--night include renders them)");
    if (skip_night && night > 0)
        std::printf("skipping %zu of %zu instants at night (sun below %.0f degrees; --night include keeps them)\n",
                    night, times.size(), kNightElevationDeg);
    if (down > (skip_night ? night : 0))
        std::fprintf(stderr, "terrashade: warning: the sun is below the horizon in %zu of %zu frames: those "
                             "have twilight or night sky light only%s\n",
                     down - (skip_night ? night : 0), frames.size(),
                     skip_night ? "" : " (--night skip leaves out those below -6 degrees)");
    for (std::size_t k = 0; k < frames.size(); ++k) {
        char name[96];
        std::snprintf(name, sizeof name, "frame_%04zu_%s.%s", k, instant_for_file_name(frames[k].time).c_str(),
                      a.format.c_str());
        frames[k].file = name;
        frames[k].index = k;
    }
    if (!shard.whole()) {
        const IndexRange part = frame_range(frames.size(), shard);
        std::printf("shard %s: frames %zu..%zu of %zu\n", shard_text(shard).c_str(), part.begin,
                    part.end == 0 ? 0 : part.end - 1, frames.size());
        frames = std::vector<Frame>(frames.begin() + std::ptrdiff_t(part.begin), frames.begin() + std::ptrdiff_t(part.end));
        if (frames.empty()) {
            claim_folder();
            write_times_csv(std::filesystem::path(a.out_dir) / "times.csv", frames, a.format == "exr");
            write_shard_marker(a.out_dir, shard);
            std::printf("shard %s has no frames (more shards than frames)\n", shard_text(shard).c_str());
            return;
        }
    }
    interrupt::report_progress("frames", frames.size());

    const ComputeDevice device(a.render.device);  // before the scene: it must outlive it
    device.apply(options);
    std::printf("visibility, transfer and sky shading on %s\n", device.name().c_str());
    std::fflush(stdout);  // said before the long part, also into a pipe or a log
    const Stopwatch t0;
    std::unique_ptr<render::Scene> scene;
    {
        ProgressBar bar("visibility", std::uint64_t(dem.width) * dem.height * std::uint64_t(directions), "rays");
        render::SceneOptions with_bar = options;
        with_bar.renderer.progress = &bar;
        scene = std::make_unique<render::Scene>(dem, with_bar);
    }
    print_stages(render_args, *scene);
    const double setup_s = t0.seconds();
    claim_folder();
    // An interrupt leaves times.csv listing exactly the frames on disk.
    interrupt::InterruptIndex& index_of_frames =
        interrupt::index_on_interrupt((std::filesystem::path(a.out_dir) / "times.csv").string(), kTimesHeader,
                                      frames.size());
    MeshMotion motion;
    auto place_mesh = [&](const Frame& fr) {
        if (path.empty()) return;
        const Stopwatch tm;
        const visibility::TexelRect r = scene->move_mesh(0, pose_on_path(path, fr.offset_s, options.meshes[0].placement));
        motion.seconds += tm.seconds(), motion.texels += r.texels(), ++motion.moves;
    };

    render::LinearImage image;
    const bool linear = a.format == "exr";
    const bool per_frame_auto = exposure.automatic && !linear;
    std::optional<render::SequenceExposure> sequence;
    double reference_ev = 0;
    if (per_frame_auto) {
        // The reference: the auto exposure of the frame with the highest sun.
        std::size_t brightest = 0;
        for (std::size_t k = 1; k < frames.size(); ++k)
            if (frames[k].sun.elevation_deg > frames[brightest].sun.elevation_deg) brightest = k;
        place_mesh(frames[brightest]);
        scene->render(scene->on_grid(frames[brightest].sun), image);
        reference_ev = render::ev100_of_scale(render::image_exposure_scale(image, exposure));
        render::SequenceExposureOptions sequence_options;
        sequence_options.max_boost_ev = a.exposure_boost_ev.value_or(sequence_options.max_boost_ev);
        sequence.emplace(reference_ev, sequence_options);
    }
    const Stopwatch t1;
    double render_s = 0;
    int width = 0, height = 0;
    double ev_min = 1e300, ev_max = -1e300;
    {
        // Frame k is tone-mapped, encoded and renamed into place on a writer thread while
        // frame k+1 renders (encoding a PNG takes about as long as relighting it). With an
        // automatic exposure a frame waits for the frames its exposure averages over
        // (sequence_exposure.hpp): at most `lookahead` frames are held.
        render::BackgroundWriter writer(a.write_queue, a.writer_threads);
        ProgressBar bar("relight", frames.size(), "frames");
        std::deque<std::pair<std::size_t, render::LinearImage>> held;
        const auto write_frame = [&](std::size_t k, render::LinearImage& frame_image) {
            Frame& fr = frames[k];
            render::Exposure frame_exposure = exposure;
            if (sequence) {
                frame_exposure.automatic = false;
                frame_exposure.ev100 = sequence->ev(k);
            }
            fr.ev100 = frame_exposure.automatic ? 0.0 : frame_exposure.ev100;
            ev_min = std::min(ev_min, fr.ev100), ev_max = std::max(ev_max, fr.ev100);
            const std::string frame_path = (std::filesystem::path(a.out_dir) / fr.file).string();
            index_of_frames.set(k, frame_path, times_csv_row(fr, linear));
            writer.write(frame_path, frame_image, frame_exposure, scene->target().georef());
            bar.advance();
        };
        const auto write_decided = [&] {
            while (!held.empty() && (!sequence || held.front().first < sequence->decided())) {
                write_frame(held.front().first, held.front().second);
                held.pop_front();
            }
        };
        for (std::size_t k = 0; k < frames.size(); ++k) {
            Frame& fr = frames[k];
            const Stopwatch tf;
            place_mesh(fr);
            scene->render(scene->on_grid(fr.sun), image);
            render_s += tf.seconds();
            width = image.width, height = image.height;
            if (sequence)
                sequence->add(render::ev100_of_scale(render::image_exposure_scale(image, exposure)), fr.offset_s);
            held.emplace_back(k, std::move(image));
            image = render::LinearImage{};
            write_decided();
        }
        if (sequence) sequence->finish();
        write_decided();
        writer.finish();
    }
    write_times_csv(std::filesystem::path(a.out_dir) / "times.csv", frames, linear);
    index_of_frames.forget();
    if (!shard.whole()) write_shard_marker(a.out_dir, shard);
    const double total_s = t1.seconds();
    if (per_frame_auto)
        std::printf("exposure: automatic per frame, averaged over up to %d frames each side within ~%.0f minutes: "
                    "EV100 %.2f to %.2f (at most %g EV brighter than the highest sun's %.2f; --exposure EV fixes one)\n",
                    render::SequenceExposureOptions{}.half_window, render::SequenceExposureOptions{}.tau_s / 60.0,
                    ev_min, ev_max, a.exposure_boost_ev.value_or(render::SequenceExposureOptions{}.max_boost_ev),
                    reference_ev);
    if (motion.moves > 0) {
        // The same recompute over the whole grid, once, in this run: what each frame would cost
        // without the footprint rectangles.
        const Stopwatch tw;
        scene->recompute_blockers();
        const double whole_s = tw.seconds();
        const double per_frame = motion.seconds / double(motion.moves);
        std::printf("mesh %s along %s: %.2f ms a frame recomputing %.0f texels on average (old and new footprints); "
                    "the whole grid's recompute %.2f ms (%.1fx slower), the scene from scratch %.3f s\n",
                    options.meshes[0].name.c_str(), a.mesh_path.c_str(), 1e3 * per_frame,
                    double(motion.texels) / double(motion.moves), 1e3 * whole_s, whole_s / per_frame, setup_s);
    }
    const double px = double(width) * height * double(frames.size());
    std::printf("relit %zu frames (%dx%d) into %s (with times.csv): visibility + transfer once %.3f s; frames %.3f s "
                "rendering (%.1f Mpx/s), %.3f s with files written (%.1f Mpx/s)\n",
                frames.size(), width, height, a.out_dir.c_str(), setup_s, render_s, px / render_s * 1e-6, total_s,
                px / total_s * 1e-6);
}

}  // namespace

void add_relight_command(CLI::App& root) {
    auto a = std::make_shared<RelightArgs>();
    CLI::App* cmd = root.add_subcommand(
        "relight",
        "The same DEM relit for many instants: visibility once, then one frame per time, named with its number and "
        "instant (frame_0000_2025-06-21T0400Z.png, ...), and times.csv (file, time, sun, exposure of each frame). "
        "Automatic exposure is per frame, averaged over neighbouring frames; times with the sun below the horizon have sky light only.");
    add_render_options(*cmd, a->render);
    cmd->add_option("--times", a->times, "START/END/STEP, ISO 8601 (e.g. 2025-06-21T04:00Z/2025-06-21T20:00Z/PT1H)");
    cmd->add_option("--times-file", a->times_file, "A file with one ISO 8601 instant per line (# comments)");
    cmd->add_option("-o,--out", a->out_dir, "Output directory (created if missing; one series per folder)")->required();
    cmd->add_flag("--overwrite", a->overwrite,
                  "Replace the frame series already in --out (its frames and times.csv; other files stay)");
    cmd->add_option("--format", a->format, "Frame format: png, tif (8-bit sRGB, georeferenced for maps) or exr (linear)")
        ->capture_default_str()
        ->check(CLI::IsMember({"png", "tif", "exr"}));
    cmd->add_option("--write-queue", a->write_queue,
                    "Frames that may wait for the writer threads (they encode frame k while frame k+1 renders)")
        ->capture_default_str()
        ->check(within(1, 64));
    cmd->add_option("--writer-threads", a->writer_threads,
                    "Threads encoding and writing frames, each its own frame (frames may then land out of order)")
        ->capture_default_str()
        ->check(within(1, 64));
    cmd->add_option("--exposure-boost", a->exposure_boost_ev,
                    "With automatic exposure: how many EV a frame may be brightened beyond the highest sun's frame. "
                    "Default 10: the physical sky's dawn (6 EV under noon) at its own exposure, its twilight (10-13 EV "
                    "under) a dark blue, the night black; 3 suits Preetham's sky")
        ->check(CLI::Range(0.0, 20.0));
    add_shard_option(*cmd, a->shard);
    cmd->add_option("--mesh-path", a->mesh_path,
                    "The first --mesh follows this flight path (CSV t_s,lon,lat,height_m,heading_deg,pitch_deg,roll_deg; "
                    "t_s from the first instant, heights above the datum; give --at only for the other meshes): per "
                    "frame only its old and new footprints are recomputed (docs/blockers.md)");
    add_night_options(*cmd, a->night);
    cmd->callback([a] { run_relight(*a); });
}

}  // namespace ts::app
