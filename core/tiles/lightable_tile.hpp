#pragma once
// The bytes of one lightable data tile (docs/web-map.md, "The data tile"): what a reader needs to
// light the tile as `relief` does for any sun and sky, quantised per tile.
//
// Relief lights the texels of its zoom's DEM level, then samples each pixel from them by
// Catmull-Rom. A lightable tile keeps the same two steps apart: the data of the window of texels
// the tile's pixels sample, and where each pixel samples them. A reader lights the texels, then
// resamples their grey as relief does, so both agree wherever the light agrees; and a zoom that
// magnifies its level stores its texels, not its pixels (a 256-px tile at 4x magnification holds
// 67 x 67 texels).
//
// One 8-bit greyscale PNG, W = max(size, window width) bytes wide: `header rows` of binary
// header, then planes, each starting on a new row:
//   pixels: coverage (size x size): 255 where relief's pixel shows data, 0 elsewhere
//   texels (window width x height), row-major:
//     valid: 255 where every value is finite
//     normal: east and north components at 12 bits, q = round((n + 1) / 2 * 4095): high 8 bits of
//       each (2 planes), their low 4 bits (east << 4 | north); up = sqrt(1 - e^2 - n^2)
//     3 planes: the land's albedo (linear R, G, B of the job's palette, snow line and land
//       cover, as `color` colours the texel), a_c = lo_c + q / 255 (hi_c - lo_c)
//     K planes: the window's principal components of the diffuse transfer T_d (9 SH coefficients,
//       bands 0..2, the bounced light's included): T = mean + sum_k w_k basis_k,
//       w_k = lo_k + q / 255 (hi_k - lo_k)
//     4 planes: the bounced light's transfer T_b, bands 0..1 (its sun part: E_sun <T_b, Y(s)>),
//       b_i = lo_i + q / 255 (hi_i - lo_i)
//     P planes: horizon elevations at the stored azimuths, h = lo_p + q / L (hi_p - lo_p)
//       radians (q = 0..L, L the header's horizon levels), clamped to the sun's band in that direction (sun_bands; a horizon below it
//       lets every sun there through, one above it hides every sun there), so most of a plane is
//       one value; azimuths the sun never reaches at the tile set's latitude are left out.
//       Stored as differences (mod 256, every texel) from a prediction by the plane before:
//       plane j keeps q_j - pred_j(q_{j-1}), pred_j(q) = floor(clamp((lo_{j-1} + q (hi_{j-1} -
//       lo_{j-1}) / L - lo_j) / (hi_j - lo_j) * L, 0, L) + 0.5) in double from the header's
//       float32 ranges, evaluated in that order, except plane 0, every key-interval-th plane and a plane whose
//       direction is not the previous plane's + 1 (those keep q_j); neighbouring azimuths'
//       horizons differ little, so most differences are 0. Rows interleave (row r of plane j is
//       row r * P + j of the block).
// Header (little-endian): "TSL1", u8 version 3, u8 K, u16 D (light directions: azimuth of
// direction d = 360 d / D degrees clockwise from north), u16 P, u16 size, u16 header rows, u16 W,
// u8 separable, u8 grid step, u32 level width, u32 level height, u32 window x0, u32 window y0,
// u16 window width, u16 window height, u16 horizon key interval (0: no plane is predicted),
// u16 horizon levels L, P u16 (the stored directions, ascending), zero padding
// to 4 bytes, then float32: P pairs (horizon lo, hi of each plane: the tile's range within the
// sun's band in that direction, clamped there); albedo lo[3], hi[3]; mean[9]; basis[K][9]; w lo[K]; w hi[K];
// bounce lo[4], hi[4]; then where
// pixels sample the level, in level texel-centre coordinates minus the window's origin:
//   separable (geographic and Web Mercator DEMs): x of each column [size], y of each row [size],
//     clamped to the level as relief clamps them
//   otherwise: x, y at every `grid step` pixels, ((size / step + 1)^2 nodes, row-major, x then
//     y per node; NaN off the CRS's domain), interpolated bilinearly between nodes, then clamped
// Why: a grey PNG any browser decodes; planes keep each quantity's neighbours adjacent for PNG's
// row filters; per-tile ranges and components spend the 8 bits where the tile's values are.
#include <cstdint>
#include <vector>

namespace ts::tiles {

// Per source texel and tile pixel, in this order: normal (3), albedo (3), transfer (9), the
// bounced light's sun part (4: bands 0..1 of T_b), horizons (D).
inline constexpr int kLightNormal = 0;
inline constexpr int kLightAlbedoAt = 3;
inline constexpr int kLightTransferAt = 6;
inline constexpr int kLightTransfer = 9;
inline constexpr int kLightBounceAt = kLightTransferAt + kLightTransfer;
inline constexpr int kLightBounce = 4;
inline constexpr int kLightHorizonAt = kLightBounceAt + kLightBounce;
inline constexpr int lightable_channels(int directions) { return kLightHorizonAt + directions; }

// Where the sun can be seen from one light direction: its lowest and highest elevation (radians)
// over a year in the two intervals between the direction and its neighbours.
struct SunBand {
    int direction = 0;
    double lowest_rad = 0, highest_rad = 0;
};

struct LightableEncoding {
    int directions = 32;
    int components = 4;               // principal components of the transfer kept (1..9)
    std::vector<struct SunBand> bands;  // stored directions, ascending (sun_bands)
    int deflate_level = 9;            // libdeflate's: tiles are made once and fetched often
};

// The directions the sun shines from at `latitude_deg` on some day of a year (above -2 degrees
// on either side of the direction: the reader interpolates between adjacent directions), each
// with the sun's band there.
std::vector<SunBand> sun_bands(double latitude_deg, int directions, double grid_north_deg = 0.0);
// The sun's highest elevation over a year at a latitude, radians.
double max_sun_elevation_rad(double latitude_deg);

// The window of a zoom's level a tile's pixels sample, with its texels' values
// (lightable_channels(D) floats each, row-major).
struct LightableTexels {
    int level_width = 0, level_height = 0;
    int x0 = 0, y0 = 0, width = 0, height = 0;
    const float* values = nullptr;
};

// Where a tile's pixels sample the window (see the header comment) and which show data.
struct LightablePixels {
    int size = 256;
    const std::uint8_t* covered = nullptr;  // size^2
    bool separable = true;
    int grid_step = 8;                      // non-separable maps
    std::vector<float> x, y;                // separable: size each; else one per grid node
};

std::vector<std::uint8_t> encode_lightable_tile(const LightableTexels& texels, const LightablePixels& pixels,
                                                const LightableEncoding& encoding);

}  // namespace ts::tiles
