#pragma once
// Horn hillshades of one tile, from heights sampled on the tile's pixels with a 1-pixel halo,
// gradients taken in map metres as gdaldem does on an EPSG:3857 raster. Web Mercator stretches
// the map by sec(lat) = cosh(y / R) at northing y, so row j's vertical scale is
//   z_j = vertical_scale * cosh(y_j / R)
// which makes its slopes true ground slopes: gdaldem hillshade -z z_j on these pixels gives row j
// (tests/cli/tiles_cli_test.cpp checks it). y_j is the row's global pixel centre, so a row is
// shaded the same in every tile that holds it.
#include <cstdint>
#include <vector>

#include "core/tiles/tile_pixels.hpp"

namespace ts::tiles {

struct HornLight {
    double azimuth_deg = 315.0;   // clockwise from north (hillshade only)
    double altitude_deg = 45.0;
};

// heights: (size + 2)^2 floats, row-major with the halo; out: size^2 values 1..255, written only
// where `covered` (size^2 bytes, nonzero = covered) says so; 0 where the pixel's own height is
// NaN (outside the terrain). A NaN elsewhere in the 3x3 window takes the centre's height.
void horn_hillshade(const TileFrame& f, const std::vector<float>& heights, double vertical_scale,
                    const HornLight& light, const std::uint8_t* covered, std::uint8_t* out);
// gdaldem -multidirectional (Mark 1992: azimuths 225, 270, 315, 360 weighted by aspect).
void horn_multidirectional(const TileFrame& f, const std::vector<float>& heights, double vertical_scale,
                           const HornLight& light, const std::uint8_t* covered, std::uint8_t* out);

// The light's constants of the multidirectional shade, once per tile.
struct MultidirectionalLight {
    explicit MultidirectionalLight(double altitude_deg);
    double sin127, cos127, cos225_cos127, flat;
};
// One pixel of the multidirectional shade, 1..255, from gradients in m/m including the vertical
// scale (exposed for tests).
std::uint8_t multidirectional_value(double dz_de, double dz_dn, const MultidirectionalLight& light);

}  // namespace ts::tiles
