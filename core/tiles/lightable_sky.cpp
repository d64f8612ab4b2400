#include "core/tiles/lightable_sky.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "core/light/sky_sh.hpp"
#include "core/render/shading_state.hpp"
#include "core/tiles/tile_set_info.hpp"

namespace ts::tiles {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", v);
    return text;
}

// One sky's table: "elevations", "sh" (27 numbers per elevation: coefficient-major, RGB), "sun"
// (RGB irradiance, 0 when the disc is down), "sun_radius_rad".
std::string sky_table_json(const light::SkyOptions& options) {
    std::string els, sh, sun;
    double radius = 0;
    light::DiffuseSkyProjector diffuse;  // as FrameRenderer
    for (double e : lightable_sky_elevations()) {
        const render::SunState state{90.0, e};
        const auto sky = light::make_sky(options, render::sun_direction(state));
        const light::SkySh projected = diffuse.project(*sky);
        const light::SunDisc disc = sky->sun();
        radius = disc.angular_radius_rad;
        // As FrameRenderer: the disc's top above the horizon and some light.
        const bool up = (disc.irradiance.x > 0 || disc.irradiance.y > 0 || disc.irradiance.z > 0) &&
                        e > -disc.angular_radius_rad / kDeg;
        els += (els.empty() ? "" : ",") + number(e);
        sh += sh.empty() ? "[" : ",[";
        for (int i = 0; i < 9; ++i)
            for (int c = 0; c < 3; ++c) sh += (i || c ? "," : "") + number(projected[std::size_t(i)][c]);
        sh += "]";
        sun += sun.empty() ? "[" : ",[";
        for (int c = 0; c < 3; ++c) sun += (c ? "," : "") + number(up ? disc.irradiance[c] : 0.0);
        sun += "]";
    }
    return "{\"describe\":\"" + light::make_sky(options, {0, 0, 1})->describe() + "\",\"elevations\":[" + els +
           "],\"sh\":[" + sh + "],\"sun\":[" + sun + "],\"sun_radius_rad\":" + number(radius) + "}";
}

}  // namespace

std::vector<double> lightable_sky_elevations() {
    std::vector<double> out;
    for (int k = 0; k <= 72; ++k) out.push_back(-6.0 + 0.25 * k);
    for (int e = 13; e <= 90; ++e) out.push_back(e);
    return out;
}

std::array<light::Rgb, 9> turn_sky_sh(const std::array<light::Rgb, 9>& in, double azimuth_deg) {
    // f'(phi) = f(phi - a) with a the sun's internal azimuth (counter-clockwise from east, where
    // the table has it at 0): (c_m, c_-m) turn by m a (cos for m > 0, sin for m < 0).
    const double a = (90.0 - azimuth_deg) * kDeg;
    std::array<light::Rgb, 9> out = in;
    for (int l = 1; l <= 2; ++l)
        for (int m = 1; m <= l; ++m) {
            const int ip = l * l + l + m, in_ = l * l + l - m;
            const float c = float(std::cos(m * a)), s = float(std::sin(m * a));
            out[std::size_t(ip)] = in[std::size_t(ip)] * c - in[std::size_t(in_)] * s;
            out[std::size_t(in_)] = in[std::size_t(in_)] * c + in[std::size_t(ip)] * s;
        }
    return out;
}

std::string lightable_json(const TileShading& s, const LightableSite& site, const std::array<float, 16>& flat_transfer,
                           const std::vector<SunBand>& stored) {
    std::string flat, dirs;
    for (int i = 0; i < 9; ++i) flat += (i ? "," : "") + number(flat_transfer[std::size_t(i)]);
    for (std::size_t i = 0; i < stored.size(); ++i) dirs += (i ? "," : "") + std::to_string(stored[i].direction);
    light::SkyOptions clear = s.sky, overcast = s.sky;
    // The clear sky is the job's clear model (the physical one unless Preetham's was asked for).
    if (clear.kind != light::SkyOptions::Kind::preetham) clear.kind = light::SkyOptions::Kind::physical;
    overcast.kind = light::SkyOptions::Kind::overcast;
    const std::string default_sky = s.sky.kind == light::SkyOptions::Kind::overcast ? "overcast" : "clear";
    // The palette as the tiles hold it (fitted to the job's heights): the page's legend.
    std::string stops;
    for (const render::PaletteStop& p : s.colors.palette.stops())
        stops += (stops.empty() ? "[" : ",[") + number(p.value) + "," + number(p.srgb.x) + "," + number(p.srgb.y) + "," +
                 number(p.srgb.z) + "]";
    // A palette read from a file is named by the file's name (no folders), quoted as JSON.
    const std::string palette_name = std::filesystem::path(s.colors.palette.name()).filename().string();
    const std::string colors = "{\"name\":" + json_string(palette_name) + ",\"stops\":[" + stops +
                               "],\"snow_line_m\":" + (s.colors.snow_line_m ? number(*s.colors.snow_line_m) : "null") +
                               ",\"exposure\":" + number(kColorExposure) + "}";
    return "{\"format\":\"terrashade-lightable\",\"version\":2,\"site\":{\"longitude_deg\":" + number(site.longitude_deg) +
           ",\"latitude_deg\":" + number(site.latitude_deg) + ",\"height_m\":" + number(site.height_m) +
           ",\"grid_north_deg\":" + number(site.grid_north_deg) + "},\"relief_contrast\":" + number(s.relief_contrast) + ",\"flat_grey\":0.5,\"light_directions\":" +
           std::to_string(s.light_directions) + ",\"stored_directions\":[" + dirs + "],\"components\":" +
           std::to_string(s.light_components) + ",\"flat_transfer\":[" + flat + "],\"colors\":" + colors + ",\"sky\":\"" + default_sky +
           "\",\"skies\":{\"clear\":" + sky_table_json(clear) + ",\"overcast\":" + sky_table_json(overcast) + "}}\n";
}

}  // namespace ts::tiles
