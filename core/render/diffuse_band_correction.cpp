#include "core/render/diffuse_band_correction.hpp"

#include <cmath>
#include <numbers>

#include "core/render/transfer.hpp"

namespace ts::render {

void correct_diffuse_bands(const std::array<float, 4>& lobe, sh::ExpMethod method, float* t, std::size_t n,
                           const std::array<float, 16>& open_log_visibility) {
    std::array<float, 16> v0 = open_log_visibility;
    const std::array<float, 3> z = {0, 0, 1};
    TransferInputs in;
    in.texels = 1;
    in.log_visibility = v0.data();
    in.lobe_axis = z.data();
    in.lobe_log_zh = lobe.data();
    in.uniform_lobe = true;
    in.method = method;
    in.threads = 1;
    std::array<float, 16> e{};
    transfer_vectors(in, e.data());  // about the z axis: the ZH of exp(F) sits at the m = 0 entries
    const double pi = std::numbers::pi;
    const double c[4] = {std::sqrt(pi) / 2 / pi, std::sqrt(pi / 3) / pi, std::sqrt(5 * pi) / 8 / pi, 0.0};
    float scale[4];
    for (int l = 0; l < 4; ++l) scale[l] = l == 3 ? 0.0f : float(c[l] / e[std::size_t(l * l + l)]);
    for (int l = 0; l < 4; ++l)
        for (int m = -l; m <= l; ++m) {
            float* p = t + std::size_t(l * l + l + m) * n;
            for (std::size_t k = 0; k < n; ++k) p[k] *= scale[l];
        }
}

}  // namespace ts::render
