#pragma once
// C++ view of the sun disc's visible fraction shared with GLSL (sun_disc_shared.h), in double,
// inside ts::visibility::shared.
#include <algorithm>
#include <cmath>

namespace ts::visibility::shared {
using std::acos;
using std::clamp;
using std::sqrt;
#include "core/visibility/sun_disc_shared.h"
}  // namespace ts::visibility::shared
