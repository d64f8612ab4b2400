#pragma once
// C++ view of the sky integrals shared with GLSL (sky_shared.h), in double, inside
// ts::visibility::shared. Use sky_integrals.hpp; this header is for the GPU agreement test.
#include <cmath>

namespace ts::visibility::shared {
using std::abs;
using std::cos;
using std::sin;
#include "core/visibility/sky_shared.h"
}  // namespace ts::visibility::shared
