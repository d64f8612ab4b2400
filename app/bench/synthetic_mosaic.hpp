#pragma once
// A synthetic SRTM1-like mosaic for memory and speed studies of DEMs larger than the shipped
// ones (`bench tiles synthetic:N`): N x N texels of 1 arc-second in EPSG:4326, the north-west
// corner at 41 N 40 E (N = 10801 is the 3x3-degree mosaic N38-41 E40-43), with ridged multi-octave value noise
// from 0 to ~3000 m (mountain ranges, valleys, no voids). Deterministic: the same N gives the
// same heights.
#include "core/dem/dem.hpp"

namespace ts::app {

dem::Dem synthetic_mosaic(int n, int threads = 0);

}  // namespace ts::app
