#pragma once
// C++ view of what a sphere hides from a receiver, shared with GLSL (sphere_occlusion_shared.h):
// the same text compiled with TS_REAL = double and TS_VEC3 = glm::dvec3, inside
// ts::blockers::shared. The nicer wrappers are sun_disc_occlusion.hpp; this header is for code
// that must follow the GPU's formula (tests, the GPU agreement test).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace ts::blockers::shared {
using glm::cross;
using glm::dot;
using glm::length;
using std::abs;
using std::acos;
using std::asin;
using std::clamp;
using std::max;
using std::min;
using std::sin;
using std::sqrt;
// GLSL's two-argument atan.
inline double atan(double y, double x) { return std::atan2(y, x); }
#include "core/blockers/sphere_occlusion_shared.h"
}  // namespace ts::blockers::shared
