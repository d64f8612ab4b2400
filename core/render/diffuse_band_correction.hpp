#pragma once
// RendererOptions::band_correction as a step of its own, for every diffuse transfer (the
// terrain's texels, a mesh's vertices): scales each SH band l of T_d by c_l / e_l, with c_l the
// clamped cosine / pi projected to order 4 (c_3 = 0) and e_l what the exponentiation gives for
// the same lobe with nothing blocking, so an open receiver gets the projected clamped cosine
// exactly (docs/accuracy.md).
#include <array>
#include <cstddef>

#include "core/sh/exp_method.hpp"

namespace ts::render {

// `lobe` the diffuse log-ZH the transfer was made with, `method` its exponentiation;
// `transfer` is [16][n] band-sequential. `open_log_visibility`: the log-SH visibility an open
// receiver has (nothing blocking: all zero; a terrain texel: level_log_visibility, its own
// plane as horizon, whose log floor below it is not zero), about +z.
void correct_diffuse_bands(const std::array<float, 4>& lobe, sh::ExpMethod method, float* transfer, std::size_t n,
                           const std::array<float, 16>& open_log_visibility = {});

}  // namespace ts::render
