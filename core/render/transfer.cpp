#include "core/render/transfer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <glm/vec3.hpp>

#include "core/sh/sh_exp.hpp"
#include "core/sh/sh_exp_shared.hpp"
#include "core/sh/sh_exp_squaring_shared.hpp"
#include "core/sh/sh_shared.hpp"
#include "core/util/parallel_for.hpp"

namespace ts::render {
namespace {

constexpr int kCoeffs = 16;
// Texels per work item of transfer_vectors: a few hundred microseconds of work each, so two
// threads share the load evenly even where the exponentials cost differently (more squarings
// under deep horizons).
constexpr std::size_t kTransferItem = 2048;
// Texels per unit of work of shade_transfer (threads take equal runs of these).
constexpr std::size_t kShadeBlock = 1024;

// The lobe's log-SH: its log-ZH turned to the axis (sh_shared.h's ts_zh_rotate, in double as the
// rest of core/sh does it; the GPU runs the same formula in float).
void rotated_lobe(const double (&zh)[4], const float* axis, float out[kCoeffs]) {
    double f[kCoeffs];
    sh::shared::ts_zh_rotate(zh, glm::dvec3(axis[0], axis[1], axis[2]), f);
    for (int i = 0; i < kCoeffs; ++i) out[i] = static_cast<float>(f[i]);
}

void check(const TransferInputs& in, const float* out) {
    if (in.texels == 0) return;
    if (!in.log_visibility || !in.lobe_axis || !in.lobe_log_zh || !out)
        throw std::invalid_argument("transfer_vectors: null input or output array");
}

// Eight texels at a time (GCC/Clang vector extension: two SSE registers, or one AVX register on
// the clone built for it), the three channel sums held in registers while the 16 coefficient
// planes stream past: each T value is loaded once and used for three multiply-adds.
using Float8 = float __attribute__((vector_size(32)));

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
// One clone for AVX2 + FMA machines (8 lanes, fused multiply-add), picked at load time.
#define TS_SHADE_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define TS_SHADE_CLONES
#endif

struct LightPlanes {
    float r[16], g[16], b[16];
};

TS_SHADE_CLONES void shade_range(const float* transfer, std::size_t texels, std::size_t t0, std::size_t t1,
                                 const LightPlanes& light, glm::vec3* rgb) {
    std::size_t t = t0;
    for (; t + 8 <= t1; t += 8) {
        Float8 r = {}, g = {}, b = {};
        for (int i = 0; i < kCoeffs; ++i) {
            Float8 c;
            std::memcpy(&c, transfer + std::size_t(i) * texels + t, sizeof c);
            r += c * light.r[i];
            g += c * light.g[i];
            b += c * light.b[i];
        }
        for (int k = 0; k < 8; ++k) rgb[t + std::size_t(k)] = glm::vec3(r[k], g[k], b[k]);
    }
    for (; t < t1; ++t) {
        float r = 0.0f, g = 0.0f, b = 0.0f;
        for (int i = 0; i < kCoeffs; ++i) {
            const float c = transfer[std::size_t(i) * texels + t];
            r += c * light.r[i];
            g += c * light.g[i];
            b += c * light.b[i];
        }
        rgb[t] = glm::vec3(r, g, b);
    }
}

}  // namespace

void transfer_vectors(const TransferInputs& in, float* transfer_out) {
    check(in, transfer_out);
    const std::size_t texels = in.texels;
    if (texels == 0) return;
    const sh::ExpOptions exp_options;
    const int items = int((texels + kTransferItem - 1) / kTransferItem);
    double uniform_zh[4] = {0, 0, 0, 0};
    if (in.uniform_lobe)
        for (int l = 0; l < 4; ++l) uniform_zh[l] = in.lobe_log_zh[l];

    parallel_for(items, thread_count(in.threads), [&](int item, int) {
        const std::size_t t_end = std::min(texels, std::size_t(item + 1) * kTransferItem);
        float v[kCoeffs], lobe[kCoeffs], f[kCoeffs], t[kCoeffs];
        double zh[4];
        for (std::size_t tx = std::size_t(item) * kTransferItem; tx < t_end; ++tx) {
            for (int i = 0; i < kCoeffs; ++i) v[i] = in.log_visibility[std::size_t(i) * texels + tx];
            if (std::isnan(v[0])) {  // a void receiver: T = NaN, without the exponentiation
                for (int i = 0; i < kCoeffs; ++i)
                    transfer_out[std::size_t(i) * texels + tx] = std::numeric_limits<float>::quiet_NaN();
                continue;
            }
            if (in.uniform_lobe) {
                rotated_lobe(uniform_zh, in.lobe_axis + 3 * tx, lobe);
            } else {
                for (int l = 0; l < 4; ++l) zh[l] = in.lobe_log_zh[4 * tx + std::size_t(l)];
                rotated_lobe(zh, in.lobe_axis + 3 * tx, lobe);
            }
            if (in.method == sh::ExpMethod::hybrid) {
                // The one definition the GPU runs too (core/sh/sh_exp_shared.h).
                sh::exp_shared::ts_transfer_vector(v, lobe, exp_options.hybrid_threshold, exp_options.max_squarings,
                                                   t);
            } else if (in.method == sh::ExpMethod::scaling_squaring) {
                // Likewise core/sh/sh_exp_squaring_shared.h (render_transfer.comp runs it too).
                sh::exp_shared::ts_transfer_vector_by(TS_TRANSFER_EXP_SCALING_SQUARING, v, lobe,
                                                      exp_options.hybrid_threshold, exp_options.squaring_base_order,
                                                      exp_options.squaring_threshold, exp_options.max_squarings, t);
            } else {
                bool void_texel = false;
                for (int i = 0; i < kCoeffs; ++i) {
                    f[i] = v[i] + lobe[i];
                    void_texel = void_texel || std::isnan(f[i]);
                }
                if (void_texel) std::fill(t, t + kCoeffs, std::numeric_limits<float>::quiet_NaN());
                else sh::sh_exp(in.method, f, t, exp_options);
            }
            for (int i = 0; i < kCoeffs; ++i) transfer_out[std::size_t(i) * texels + tx] = t[i];
        }
    });
}

void shade_transfer(const float* transfer, std::size_t texels, const std::array<glm::vec3, 16>& light_sh,
                    glm::vec3* rgb_out, int threads) {
    if (texels == 0) return;
    if (!transfer || !rgb_out) throw std::invalid_argument("shade_transfer: null input or output array");
    LightPlanes light;
    for (int i = 0; i < kCoeffs; ++i) {
        light.r[i] = light_sh[std::size_t(i)].r;
        light.g[i] = light_sh[std::size_t(i)].g;
        light.b[i] = light_sh[std::size_t(i)].b;
    }
    const std::size_t blocks = (texels + kShadeBlock - 1) / kShadeBlock;
    parallel_rows(int(blocks), threads, static_cast<long long>(kShadeBlock) * 48, [&](int b0, int b1) {
        shade_range(transfer, texels, std::size_t(b0) * kShadeBlock, std::min(texels, std::size_t(b1) * kShadeBlock),
                    light, rgb_out);
    });
}

}  // namespace ts::render
