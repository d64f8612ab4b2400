#pragma once
// The formulas shared with GLSL (sh_shared.h) compiled a second time in single precision, as the
// GPU runs them: TS_REAL = float, TS_VEC3 = glm::vec3, inside ts::sh::shared_float. For CPU
// kernels that vectorise across lanes of floats (core/blockers/sphere_log_sh_kernel.cpp). The
// literals of sh_shared.h are written without float suffixes (GLSL reads them as float): a
// translation unit using this header should be compiled with -fsingle-precision-constant, or
// each literal promotes its product to double.
//
// sh_shared.h has one include guard, so this header and sh_shared.hpp (the double instance)
// cannot meet in one translation unit.
#include <cmath>
#include <glm/vec3.hpp>

#ifdef TS_SH_SHARED_H
#error "core/sh/sh_shared_float.hpp and core/sh/sh_shared.hpp cannot share a translation unit"
#endif

#include "core/util/glsl_compat.h"

#undef TS_REAL
#undef TS_VEC3
#define TS_REAL float
#define TS_VEC3 glm::vec3

namespace ts::sh::shared_float {
using std::asin;
using std::cos;
using std::sin;
using std::sqrt;
#include "core/sh/sh_shared.h"
}  // namespace ts::sh::shared_float

#undef TS_REAL
#undef TS_VEC3
#define TS_REAL double
#define TS_VEC3 glm::dvec3
