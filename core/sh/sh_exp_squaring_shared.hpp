#pragma once
// C++ view of the scaling-and-squaring exponentiation shared with GLSL
// (sh_exp_squaring_shared.h), in namespace ts::sh::exp_shared next to the hybrid method.
// core/render/transfer.cpp runs it; tests/gpu/render_backend_test.cpp checks it against
// sh_exp.hpp's exp_scaling_squaring and against the shader.
#include "core/sh/sh_exp_shared.hpp"

namespace ts::sh::exp_shared {
#include "core/sh/sh_exp_squaring_shared.h"
}  // namespace ts::sh::exp_shared
