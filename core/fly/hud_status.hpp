#pragma once
// What the flythrough's HUD says, as text: the same facts in the window title and in the
// overlay drawn in the frame (core/fly/hud_text.hpp), so the two never disagree.
#include <cstddef>
#include <string>
#include <vector>

namespace ts::fly {

struct HudStatus {
    std::string lead;  // "45 fps" in the window, "frame 2/40" offscreen
    double frame_ms = 0, select_ms = 0, draw_ms = 0;
    std::size_t patches = 0, triangles = 0;
    double error_px = 0;  // the LOD's screen-space error bound
    double lon_deg = 0, lat_deg = 0, height_m = 0, heading_deg = 0;
    std::string solar_time;  // "HH:MM", mean local solar time
    double sun_elevation_deg = 0;
    std::string camera;  // chase, cockpit, free, orbit
    bool paused = false, recording = false;
    // A streamed DEM: detail tiles resident, and loading (pending < 0: not streamed).
    std::size_t tiles = 0;
    long pending_tiles = -1;
};

// Three short lines: timings, geometry and state, position and sun.
std::vector<std::string> hud_lines(const HudStatus& s);

// One line for the window title: "terrashade fly | " then the lines joined by " | ".
std::string hud_title(const HudStatus& s);

}  // namespace ts::fly
