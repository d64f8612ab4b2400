#pragma once
// C++ view of the pyramid method's per-sample math shared with GLSL (pyramid_shared.h), in
// double, inside ts::visibility::shared.
#include <algorithm>
#include <cmath>

namespace ts::visibility::shared {
using std::clamp;
using std::floor;
using std::log2;
using std::max;
#include "core/visibility/pyramid_shared.h"
}  // namespace ts::visibility::shared
