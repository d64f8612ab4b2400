#pragma once
// C++ view of the exponentiation shared with GLSL (sh_exp_shared.h, sh_product_shared.h): the
// same float text the shaders compile, inside ts::sh::exp_shared. core/render/transfer.cpp
// runs it; tests check it against core/sh (sh_product.hpp's tensor, sh_exp.hpp's exp_hybrid).
#include <algorithm>
#include <cmath>

namespace ts::sh::exp_shared {
using std::exp;
using std::isinf;
using std::isnan;
using std::log;
using std::min;
using std::sqrt;
#include "core/sh/sh_exp_shared.h"
}  // namespace ts::sh::exp_shared
