#include "core/fly/hud_status.hpp"

#include <cmath>
#include <cstdio>

namespace ts::fly {

std::vector<std::string> hud_lines(const HudStatus& s) {
    char timing[128], state[160], place[160], tiles[48] = "";
    if (s.pending_tiles >= 0)
        std::snprintf(tiles, sizeof tiles, "  tiles %zu%s", s.tiles, s.pending_tiles > 0 ? "+" : "");
    std::snprintf(timing, sizeof timing, "%s  %.1f ms (select %.2f, draw %.1f)  err<=%.2f px", s.lead.c_str(),
                  s.frame_ms, s.select_ms, s.draw_ms, s.error_px);
    std::snprintf(state, sizeof state, "%zu patches  %zu tris%s  %s%s%s", s.patches, s.triangles, tiles,
                  s.camera.c_str(), s.paused ? "  paused" : "", s.recording ? "  REC" : "");
    std::snprintf(place, sizeof place, "%.4f%c %.4f%c %.0f m  hdg %03.0f  %s solar  sun %.0f deg",
                  std::abs(s.lat_deg), s.lat_deg >= 0 ? 'N' : 'S', std::abs(s.lon_deg), s.lon_deg >= 0 ? 'E' : 'W',
                  s.height_m, s.heading_deg, s.solar_time.c_str(), s.sun_elevation_deg);
    return {timing, state, place};
}

std::string hud_title(const HudStatus& s) {
    std::string title = "terrashade fly";
    for (const std::string& l : hud_lines(s)) title += " | " + l;
    return title;
}

}  // namespace ts::fly
