#pragma once
// The slides' shading step: per texel, the log visibility plus a log-BRDF lobe, exponentiated
// once (the "transfer vector" T), then dotted with the lighting SH:
//   T_t = exp_SH(V_log,t + rotate(F_log,t, axis_t))        (16 coefficients)
//   L_out,t = sum_i T_i,t * L_i                             (per RGB channel)
// T does not depend on the light, so relighting is one 16-term dot product per channel.
// The same two steps run on the GPU (gpu/render) and are tested against these.
#include <array>
#include <cstddef>

#include <glm/vec3.hpp>

#include "core/sh/exp_method.hpp"

namespace ts::render {

struct TransferInputs {
    std::size_t texels = 0;
    const float* log_visibility = nullptr;  // [16][texels] band-sequential; NaN = void (T = NaN)
    const float* lobe_axis = nullptr;       // [texels][3] unit ENU axis: the normal (diffuse) or mirror direction (Phong)
    const float* lobe_log_zh = nullptr;     // [texels][4] log-ZH of the lobe, or one [4] if uniform_lobe
    bool uniform_lobe = false;
    sh::ExpMethod method = sh::ExpMethod::hybrid;
    int threads = 0;
};
// Writes T as [16][texels].
void transfer_vectors(const TransferInputs& in, float* transfer_out);

// rgb_out[t] = sum_i T[i][t] * light[i]; NaN texels give NaN.
void shade_transfer(const float* transfer, std::size_t texels, const std::array<glm::vec3, 16>& light_sh,
                    glm::vec3* rgb_out, int threads = 0);

}  // namespace ts::render
