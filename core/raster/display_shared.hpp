#pragma once
// C++ view of the display transform shared with GLSL (display_shared.h), in float, inside
// ts::raster::shared.
#include <algorithm>
#include <cmath>

namespace ts::raster::shared {
using std::clamp;
using std::max;
using std::min;
using std::pow;
#include "core/raster/display_shared.h"
}  // namespace ts::raster::shared
