#include "gpu/fly/fly_window_loop.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/fly/hud_text.hpp"
#include "core/raster/png_writer.hpp"
#include "core/util/atomic_file.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::gpu {
namespace {

// Mean local solar time (UTC + longitude / 15 h), "HH:MM".
std::string solar_time(light::UtcTime t, double lon_deg) {
    const double day_s = 86400.0;
    const double utc_s = std::fmod(
        double(std::chrono::duration_cast<std::chrono::seconds>(t.time_since_epoch()).count()), day_s);
    double s = std::fmod(utc_s + lon_deg / 15.0 * 3600.0 + day_s, day_s);
    char buf[16];
    std::snprintf(buf, sizeof buf, "%02d:%02d", int(s / 3600.0), int(std::fmod(s, 3600.0) / 60.0));
    return buf;
}

bool held(const WindowInput& in, int key) {
    for (int k : in.held)
        if (k == key) return true;
    return false;
}

}  // namespace

fly::CameraPose camera_for(fly::CameraMode mode, const fly::CameraPose& aircraft) {
    if (mode == fly::CameraMode::cockpit) return aircraft;
    fly::CameraPose c = fly::chase_pose(aircraft);
    return c;
}

void write_rgba_png(const std::filesystem::path& file, int w, int h, const std::vector<std::uint8_t>& rgba) {
    std::vector<std::uint8_t> rgb(std::size_t(w) * std::size_t(h) * 3);
    for (std::size_t i = 0; i < std::size_t(w) * std::size_t(h); ++i)
        for (int c = 0; c < 3; ++c) rgb[3 * i + std::size_t(c)] = rgba[4 * i + std::size_t(c)];
    write_atomically(file, [&](const std::filesystem::path& tmp) { raster::write_png(tmp, file, w, h, 3, rgb.data()); });
}

fly::HudStatus hud_status(const Flythrough& flight, const std::string& lead, const FlyFrameStats& st,
                          double frame_ms, double draw_ms, const fly::CameraPose& camera, light::UtcTime time,
                          fly::CameraMode mode, bool paused, bool recording) {
    fly::HudStatus h;
    h.lead = lead;
    h.frame_ms = frame_ms, h.select_ms = st.select_ms, h.draw_ms = draw_ms;
    h.patches = st.patches, h.triangles = st.triangles, h.error_px = st.screen_error_px;
    const glm::dvec2 ll = flight.lonlat_of(camera.eye);
    h.lon_deg = ll.x, h.lat_deg = ll.y, h.height_m = camera.eye.z, h.heading_deg = camera.heading_deg;
    h.solar_time = solar_time(time, ll.x);
    h.sun_elevation_deg = flight.sun().elevation_deg;
    h.camera = fly::camera_mode_name(mode);
    h.paused = paused, h.recording = recording;
    if (flight.streamed()) h.tiles = st.tiles_resident, h.pending_tiles = long(st.tiles_pending);
    return h;
}

void show_hud(FlyRenderer& renderer, const fly::HudStatus& status) {
    fly::HudStyle style;
    style.scale = fly::hud_scale_for_width(renderer.width());
    const int margin = 6 * style.scale;
    renderer.set_hud(fly::rasterise_hud(fly::hud_lines(status), style), margin, margin);
}

void run_window(const FlyWindowLoop& a, Flythrough& flight, FlyWindow& window, const fly::FlightPath& path,
                fly::CameraMode mode, light::UtcTime start_time) {
    std::printf("%s", a.keys_help.c_str());
    std::fflush(stdout);
    const std::string& shot_dir = a.shot_dir;
    light::UtcTime time = start_time;
    double path_t = path.start_s();
    bool paused = false;
    fly::FreeFlight free_flight;
    free_flight.pose = flight.default_pose();
    fly::Orbit orbit;
    orbit.centre = {0.0, 0.0, flight.ground_height_m({0, 0, 0})};
    orbit.distance_m = 0.5 * std::hypot(flight.frame().to_metric(0, 0).x, flight.frame().to_metric(0, 0).y);
    bool recording = false;
    std::vector<fly::FlightPose> recorded;
    double record_t = 0;
    int shots = 0;
    FlyFrameUniforms u;
    FlyFrameStats st;
    auto last = std::chrono::steady_clock::now();
    double fps_time = 0, title_time = 1.0;
    int fps_frames = 0;
    double fps = 0, frame_ms = 0, draw_ms = 0;
    fly::CameraPose camera;
    int frames_drawn = 0;
    bool hud = a.hud;
    while (true) {
        const WindowInput in = window.poll();
        if (in.close) break;
        if (a.exit_after > 0 && frames_drawn >= a.exit_after) break;
        const auto now = std::chrono::steady_clock::now();
        const double dt = std::min(0.25, std::chrono::duration<double>(now - last).count());
        last = now;
        bool quit = false;
        bool screenshot = false;
        for (int key : in.pressed) {
            switch (key) {
                case GLFW_KEY_ESCAPE: quit = true; break;
                case GLFW_KEY_C:
                    if (mode == fly::CameraMode::free) {
                        mode = fly::CameraMode::orbit;
                    } else if (mode == fly::CameraMode::orbit) {
                        mode = fly::CameraMode::chase;
                    } else if (mode == fly::CameraMode::chase) {
                        mode = fly::CameraMode::cockpit;
                    } else {
                        mode = fly::CameraMode::free;
                        free_flight.pose = camera;
                        free_flight.pose.roll_deg = 0;
                    }
                    break;
                case GLFW_KEY_SPACE: paused = !paused; break;
                case GLFW_KEY_LEFT_BRACKET: time -= std::chrono::minutes(15); break;
                case GLFW_KEY_RIGHT_BRACKET: time += std::chrono::minutes(15); break;
                case GLFW_KEY_COMMA: time -= std::chrono::hours(1); break;
                case GLFW_KEY_PERIOD: time += std::chrono::hours(1); break;
                case GLFW_KEY_EQUAL: free_flight.speed_mps *= 1.5; break;
                case GLFW_KEY_MINUS: free_flight.speed_mps /= 1.5; break;
                case GLFW_KEY_P:
                case GLFW_KEY_F12: screenshot = true; break;
                case GLFW_KEY_H:
                    hud = !hud;
                    if (!hud) flight.renderer().hide_hud();
                    title_time = 1.0;  // shown (or its title refreshed) this frame, not in 0.25 s
                    break;
                case GLFW_KEY_F1: std::printf("%s", a.keys_help.c_str()); break;
                case GLFW_KEY_K:
                    if (!recording) {
                        recording = true;
                        recorded.clear();
                        record_t = 0;
                        std::printf("recording to %s\n", a.record.c_str());
                    } else {
                        recording = false;
                        const fly::FlightPath p(recorded);
                        write_atomically(a.record, [&](const std::filesystem::path& tmp) {
                            std::ofstream(tmp) << fly::flight_path_csv(p);
                        });
                        std::printf("wrote %s (%zu poses)\n", a.record.c_str(), recorded.size());
                    }
                    break;
                default: break;
            }
        }
        if (quit) break;
        std::fflush(stdout);
        if (!paused) {
            path_t += dt;
            if (path_t > path.start_s() + path.duration_s()) path_t = path.start_s();
        }
        const double boost = held(in, GLFW_KEY_LEFT_SHIFT) ? 5.0 : 1.0;
        if (mode == fly::CameraMode::free) {
            const double f = (held(in, GLFW_KEY_W) ? 1.0 : 0.0) - (held(in, GLFW_KEY_S) ? 1.0 : 0.0);
            const double r = (held(in, GLFW_KEY_D) ? 1.0 : 0.0) - (held(in, GLFW_KEY_A) ? 1.0 : 0.0);
            const double up = (held(in, GLFW_KEY_R) ? 1.0 : 0.0) - (held(in, GLFW_KEY_F) ? 1.0 : 0.0);
            free_flight.move(f, r, up, dt * boost);
            const double turn_h = (held(in, GLFW_KEY_RIGHT) ? 60.0 : 0.0) - (held(in, GLFW_KEY_LEFT) ? 60.0 : 0.0);
            const double turn_p = (held(in, GLFW_KEY_UP) ? 40.0 : 0.0) - (held(in, GLFW_KEY_DOWN) ? 40.0 : 0.0);
            free_flight.turn(turn_h * dt + 0.15 * in.mouse_dx, turn_p * dt - 0.15 * in.mouse_dy);
            const double floor = flight.ground_height_m(free_flight.pose.eye) + 2.0;
            free_flight.pose.eye.z = std::max(free_flight.pose.eye.z, floor);
            camera = free_flight.pose;
        } else if (mode == fly::CameraMode::orbit) {
            const double turn_h = (held(in, GLFW_KEY_RIGHT) ? 45.0 : 0.0) - (held(in, GLFW_KEY_LEFT) ? 45.0 : 0.0);
            orbit.turn(turn_h * dt + 0.2 * in.mouse_dx, 0.2 * in.mouse_dy);
            if (held(in, GLFW_KEY_UP)) orbit.zoom(std::pow(0.5, dt));
            if (held(in, GLFW_KEY_DOWN)) orbit.zoom(std::pow(2.0, dt));
            camera = orbit.pose();
        } else {
            camera = camera_for(mode, flight.pose_of(path.at(path_t)));
        }
        if (recording) {
            record_t += dt;
            const fly::CameraPose& rec = mode == fly::CameraMode::free ? camera : flight.pose_of(path.at(path_t));
            if (recorded.empty() || record_t > recorded.back().t_s + 1e-3)
                recorded.push_back(flight.flight_pose_of(rec, record_t));
        }
        flight.set_time(time);

        int fw = 0, fh = 0;
        window.framebuffer_size(fw, fh);
        if (fw == 0 || fh == 0) continue;  // minimised
        if (fw != flight.renderer().width() || fh != flight.renderer().height()) {
            flight.context().device().wait_idle();
            flight.renderer().resize(fw, fh);
        }
        const Stopwatch frame_watch;
        const fly::CameraPose aircraft = flight.pose_of(path.at(path_t));
        flight.prepare(camera, u, st, mode == fly::CameraMode::cockpit ? nullptr : &aircraft);
        std::uint32_t image = 0;
        const Stopwatch draw_watch;
        if (window.begin(image)) {
            flight.renderer().record(window.commands(), u, flight.patches());
            window.end(flight.renderer().color_image(), flight.renderer().width(), flight.renderer().height(),
                       image);
        }
        draw_ms = draw_watch.milliseconds();
        frame_ms = frame_watch.milliseconds();
        if (screenshot) {
            std::vector<std::uint8_t> rgba;
            flight.renderer().render_to_memory(u, flight.patches(), rgba);
            char name[48];
            std::snprintf(name, sizeof name, "fly_screenshot_%03d.png", shots++);
            const std::filesystem::path file = std::filesystem::path(shot_dir) / name;
            write_rgba_png(file, flight.renderer().width(), flight.renderer().height(), rgba);
            std::printf("wrote %s\n", file.string().c_str());
        }
        ++fps_frames;
        ++frames_drawn;
        fps_time += dt;
        title_time += dt;
        if (fps_time >= 0.5) {
            fps = fps_frames / fps_time;
            fps_frames = 0;
            fps_time = 0;
        }
        if (title_time >= 0.25) {
            title_time = 0;
            char lead[32];
            std::snprintf(lead, sizeof lead, "%.0f fps", fps);
            const fly::HudStatus status =
                hud_status(flight, lead, st, frame_ms, draw_ms, camera, time, mode, paused, recording);
            window.set_title(fly::hud_title(status));
            // Drawn from the next frame on; the text changes at this 4 Hz, so the overlay is
            // copied to the device no more often.
            if (hud) show_hud(flight.renderer(), status);
        }
    }
    if (recording && !recorded.empty()) {
        const fly::FlightPath p(recorded);
        write_atomically(a.record, [&](const std::filesystem::path& tmp) { std::ofstream(tmp) << fly::flight_path_csv(p); });
        std::printf("wrote %s (%zu poses)\n", a.record.c_str(), recorded.size());
    }
    flight.context().device().wait_idle();
}

}  // namespace ts::gpu
