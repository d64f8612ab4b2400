#pragma once
// What a lightable tile set's reader needs besides its tiles (`lightable.json`, docs/web-map.md):
// where the sun is computed from, and the light of render's skies by the sun's elevation, in the
// sun's frame, so a browser lights a tile for any instant with the same numbers as `relief`.
//
//   site                 the DEM's centre and mean height (--time places the sun there)
//   flat_transfer        T_d of open flat ground (9 SH coefficients): relief is relative to it
//   colors               the palette's stops (metres, sRGB) the tiles' albedos come from, the
//                        snow line, and `color`'s exposure (kColorExposure)
//   skies.clear/overcast per elevation: the sky's SH (9 coefficients x RGB) with the sun at
//                        azimuth 90 (east), and the sun's irradiance (RGB), its disc's radius
// A reader turns the SH about the vertical to the sun's azimuth (lightable_sky_sh_at in C++;
// its JS twin relight.mjs), interpolating linearly between tabulated elevations.
#include <array>
#include <string>
#include <vector>

#include "core/light/sky.hpp"
#include "core/tiles/lightable_tile.hpp"
#include "core/tiles/tile_style.hpp"

namespace ts::tiles {

struct LightableSite {
    double longitude_deg = 0, latitude_deg = 0, height_m = 0;
    // Where true north lies on the DEM's grid (Georef::grid_azimuth_of_north_deg): the stored
    // directions are the grid's, so the reader turns the sun's true azimuth by it.
    double grid_north_deg = 0;
};

// The sun elevations tabulated (degrees): 0.25 apart from -6 to 12 (light changes fastest near
// the horizon), 1 apart to 90.
std::vector<double> lightable_sky_elevations();

// The sky's 9 SH coefficients (RGB) of `sky_sh` (sun at azimuth 90) turned to the sun at
// `azimuth_deg` clockwise from north: a rotation about the vertical.
std::array<light::Rgb, 9> turn_sky_sh(const std::array<light::Rgb, 9>& sky_sh, double azimuth_deg);

// The JSON text of lightable.json for a job's shading at `site`.
std::string lightable_json(const TileShading& shading, const LightableSite& site, const std::array<float, 16>& flat_transfer,
                           const std::vector<SunBand>& stored_directions);

}  // namespace ts::tiles
