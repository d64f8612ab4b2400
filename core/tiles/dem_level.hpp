#pragma once
// A DEM pyramid level as a Dem of its own (so the renderer's whole pipeline runs on it): level L
// averages 2^L x 2^L texels (terrain::downsample_2x2 applied L times, the HeightPyramid's
// prefilter), its georef scaled to match, and a texel void only where all it covers was void.
#include "core/dem/dem.hpp"

namespace ts::tiles {

dem::Dem dem_level(const dem::Dem& dem, int level, int threads = 0);

}  // namespace ts::tiles
