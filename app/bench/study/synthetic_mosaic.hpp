#pragma once
// A synthetic SRTM1-like mosaic for memory and speed studies of DEMs larger than the shipped
// ones (`bench tiles synthetic:N`, and `bench dem N` writing one to a GeoTIFF): N x N texels of
// 1 arc-second in EPSG:4326, the north-west corner at 41 N 40 E (N = 10801 is the 3x3-degree
// mosaic N38-41 E40-43), with ridged multi-octave value noise from 0 to ~3000 m (mountain
// ranges, valleys, no voids). Deterministic: the same N gives the same heights, and a texel's
// height depends on its column and row alone (not on N), so a band of rows computed apart
// equals the same rows of the whole grid.
#include <span>

#include "core/dem/dem.hpp"
#include "core/geo/georef.hpp"

namespace ts::app {

// The height of the texel (col, row), metres: the one definition of the noise.
float synthetic_height(int col, int row);

// Rows [row0, row0 + rows) of an n-column grid into `z` (rows * n heights, row-major), on
// thread_count(threads) threads: what both synthetic_mosaic and `bench dem` compute.
void synthetic_rows(int n, int row0, int rows, std::span<float> z, int threads = 0);

// The grid's georeferencing: 1 arc-second cells, the north-west texel centred on 41 N 40 E.
geo::Georef synthetic_georef(int n);

dem::Dem synthetic_mosaic(int n, int threads = 0);

}  // namespace ts::app
