#pragma once
// The flythrough's window loop: GLFW input (keys, mouse), the clock, the camera of each mode,
// screenshots and recording, the HUD and the window title, one frame drawn per pass. The `fly`
// command (app/fly_command.cpp) parses its options, makes the Flythrough and the window and
// calls run_window; its offscreen frames share camera_for, the HUD and write_rgba_png.
#include <filesystem>
#include <string>
#include <vector>

#include "core/fly/camera_rig.hpp"
#include "core/fly/flight_path.hpp"
#include "core/fly/hud_status.hpp"
#include "core/light/utc_time.hpp"
#include "gpu/fly/flythrough.hpp"
#include "gpu/fly/fly_window.hpp"

namespace ts::gpu {

// What the window loop takes from the command line.
struct FlyWindowLoop {
    std::string keys_help;   // printed at the start and on F1
    std::string shot_dir;    // screenshots' folder
    std::string record;      // the recording's CSV (the flight path format)
    bool hud = true;         // the HUD in the frame (H toggles it)
    int exit_after = 0;      // quit after this many frames; 0: when the user quits
};

// Until the window closes or Esc: flies `path` (or the free and orbit cameras), one frame a
// pass; `mode` and the time are where the user starts.
void run_window(const FlyWindowLoop& loop, Flythrough& flight, FlyWindow& window, const fly::FlightPath& path,
                fly::CameraMode mode, light::UtcTime start_time);

// The camera of a path-following mode (chase, cockpit) for the aircraft's pose.
fly::CameraPose camera_for(fly::CameraMode mode, const fly::CameraPose& aircraft);

// What the HUD and the window title say about this frame; `lead` is the fps or the frame number.
fly::HudStatus hud_status(const Flythrough& flight, const std::string& lead, const FlyFrameStats& st,
                          double frame_ms, double draw_ms, const fly::CameraPose& camera, light::UtcTime time,
                          fly::CameraMode mode, bool paused, bool recording);

// The HUD in the frame's top-left corner, its font doubled on frames wider than 1200 px.
void show_hud(FlyRenderer& renderer, const fly::HudStatus& status);

// A frame read back (RGBA) as an RGB PNG, written atomically.
void write_rgba_png(const std::filesystem::path& file, int w, int h, const std::vector<std::uint8_t>& rgba);

}  // namespace ts::gpu
