#include "core/render/relief_contrast.hpp"

#include <algorithm>
#include <cmath>

#include "core/render/tone_map.hpp"

namespace ts::render {
namespace {

bool is_land(const MaterialRaster& m, std::size_t i) {
    return !m.water[i] && m.ks[i] == 0.0f && m.albedo_r[i] > 0 && m.albedo_g[i] > 0 && m.albedo_b[i] > 0;
}

}  // namespace

ReliefContrastApplied apply_relief_contrast(std::vector<glm::vec3>& radiance, const MaterialRaster& m,
                                            const ReliefContrast& options) {
    const std::size_t n = std::min(radiance.size(), m.size());
    std::vector<float> log_e;
    log_e.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (!is_land(m, i)) continue;
        const glm::vec3 e = radiance[i] / glm::vec3(m.albedo_r[i], m.albedo_g[i], m.albedo_b[i]);
        const float l = luminance(e);
        if (l > 0 && std::isfinite(l)) log_e.push_back(std::log2(l));
    }
    if (log_e.size() < 16) return {};
    double mean = 0;
    for (float v : log_e) mean += v;
    mean /= double(log_e.size());
    double k = options.k;
    if (options.automatic) {
        auto at = [&](double q) {
            const auto idx = std::size_t(q * double(log_e.size() - 1));
            std::nth_element(log_e.begin(), log_e.begin() + std::ptrdiff_t(idx), log_e.end());
            return double(log_e[idx]);
        };
        const double spread = at(0.95) - at(0.05);
        k = spread > 0 ? std::clamp(options.target_stops / spread, 1.0, options.max_k) : 1.0;
    }
    if (k == 1.0) return {};
    const double albedo_factor = options.automatic && options.soften_albedo ? 1.0 / k : 1.0;
    const double ref = std::exp2(mean);
    for (std::size_t i = 0; i < n; ++i) {
        if (!is_land(m, i)) continue;
        const glm::vec3 a(m.albedo_r[i], m.albedo_g[i], m.albedo_b[i]);
        const glm::vec3 e = radiance[i] / a;
        const float l = luminance(e);
        if (!(l > 0) || !std::isfinite(l)) continue;
        // E' = E_ref (E/E_ref)^k with the irradiance's colour kept: scale E by E'/E.
        const float scale = float(std::pow(double(l) / ref, k - 1.0));
        const glm::vec3 a2 = albedo_factor < 1.0 ? compressed_albedo(a, albedo_factor) : a;
        radiance[i] = a2 * (e * scale);
    }
    return {k, albedo_factor};
}

}  // namespace ts::render
