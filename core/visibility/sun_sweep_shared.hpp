#pragma once
// C++ view of the sun sweep's shadow-height recursion shared with GLSL (sun_sweep_shared.h),
// in double, inside ts::visibility::shared.
namespace ts::visibility::shared {
#include "core/visibility/sun_sweep_shared.h"
}  // namespace ts::visibility::shared
