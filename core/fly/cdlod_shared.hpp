#pragma once
// C++ view of core/fly/cdlod_shared.h (the same text the terrain vertex shader compiles), in
// float as on the GPU, inside ts::fly::shared.
#include <algorithm>
#include <cmath>

namespace ts::fly::shared {
using std::floor;
using std::max;
inline float clamp(float v, float lo, float hi) { return std::min(std::max(v, lo), hi); }
#include "core/fly/cdlod_shared.h"
}  // namespace ts::fly::shared
