#pragma once
// The bytes of one lightable data tile (docs/web-map.md, "The data tile"): what a reader needs to
// light each pixel as `relief` does for any sun and sky, quantised per tile.
//
// One 8-bit greyscale PNG, `size` pixels wide: `header rows` of binary header, then planes of
// size x size bytes one below the other:
//   plane 0          coverage: 255 where the pixel has data, 0 elsewhere
//   planes 1, 2      the unit normal's east and north components, high 8 of 12 bits:
//                    q = round((n + 1) / 2 * 4095); plane 3 their low 4 bits (east << 4 | north);
//                    up = sqrt(1 - e^2 - n^2)
//   K planes         the tile's principal components of the diffuse transfer T_d (9 SH
//                    coefficients, bands 0..2): T = mean + sum_k w_k basis_k, w_k = lo_k +
//                    q / 255 (hi_k - lo_k)
//   P planes         horizon elevations at the stored azimuths: h = lo + q / 255 (hi - lo),
//                    radians; the azimuths the sun never reaches at the tile set's latitude are
//                    left out (their neighbours are kept for interpolation)
// Header (little-endian): "TSL1", u8 version 1, u8 K, u8 D (light directions: azimuth of
// direction d = 360 d / D degrees clockwise from north), u8 P, u16 size, u16 header rows,
// P bytes (the stored directions, ascending), zero padding to 4 bytes, then float32: horizon lo,
// hi; mean[9]; basis[K][9]; w lo[K]; w hi[K].
// Why this: a grey PNG any browser decodes; planes keep each quantity's neighbours adjacent, so
// PNG's row filters find them; per-tile ranges and components spend the 8 bits where the tile's
// values are (a tile's transfer vectors span few dimensions: 4 components keep it within 1%).
#include <cstdint>
#include <vector>

namespace ts::tiles {

// Per source texel and tile pixel, in this order: normal (3), transfer (9), horizons (D).
inline constexpr int kLightNormal = 0;
inline constexpr int kLightTransferAt = 3;
inline constexpr int kLightTransfer = 9;
inline constexpr int kLightHorizonAt = kLightTransferAt + kLightTransfer;
inline constexpr int lightable_channels(int directions) { return kLightHorizonAt + directions; }

struct LightableEncoding {
    int directions = 32;
    int components = 4;               // principal components of the transfer kept (1..9)
    std::vector<int> planes;          // stored directions, ascending (sun_directions)
    double max_horizon_rad = 1.5708;  // horizons above it always hide the sun (clamped)
};

// The directions whose horizons can hide the sun at `latitude_deg` on some day of a year (the
// sun above -2 degrees between them), each with its neighbours (the reader interpolates between
// adjacent directions).
std::vector<int> sun_directions(double latitude_deg, int directions);
// The sun's highest elevation over a year at a latitude, radians.
double max_sun_elevation_rad(double latitude_deg);

// A tile's bytes from its pixels' values (size * size * lightable_channels(D) floats, row-major)
// where `covered` is non-zero; pixels with a non-finite value are not covered.
std::vector<std::uint8_t> encode_lightable_tile(int size, const float* values, const std::uint8_t* covered,
                                                const LightableEncoding& encoding);

}  // namespace ts::tiles
