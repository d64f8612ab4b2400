#pragma once
// Filling voids (SRTM's -32768 holes, GeoTIFF nodata) so shading has a height everywhere.
#include "core/dem/dem.hpp"

namespace ts::dem {

// Onion-peel fill: each void takes the mean of its already-known 8-neighbours, layer by layer
// from the rim inward (breadth-first, O(cells)); then over-relaxed Laplace sweeps over the
// filled cells only turn that into the smooth (harmonic) surface the rim defines. Measured
// heights never change and void_mask is kept, so later stages can tell measured from invented.
// Throws ts::InputError if the DEM has no valid height at all.
void fill_voids(Dem& dem);

}  // namespace ts::dem
