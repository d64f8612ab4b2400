#pragma once
// C++ view of the formulas shared with GLSL (sh_shared.h): the same text compiled with
// TS_REAL = double and TS_VEC3 = glm::dvec3, inside ts::sh::shared. Use the nicer wrappers in
// sh_basis.hpp, slice_projector.hpp and core/blockers/sphere_blocker.hpp; this header is for
// code that must match the GPU bit for bit in formula (tests, the GPU agreement test).
#include <cmath>
#include <glm/vec3.hpp>

namespace ts::sh::shared {
using std::asin;
using std::cos;
using std::sin;
using std::sqrt;
#include "core/sh/sh_shared.h"
}  // namespace ts::sh::shared
