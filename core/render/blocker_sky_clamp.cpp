#include "core/render/blocker_sky_clamp.hpp"

#include <numeric>
#include <stdexcept>

#include <glm/common.hpp>

#include "core/util/parallel_for.hpp"

namespace ts::render {

BlockerSkyClamp::BlockerSkyClamp(int coefficients) : k_(coefficients) {
    if (k_ != 9 && k_ != 16) throw std::invalid_argument("BlockerSkyClamp: 9 or 16 coefficients");
}

void BlockerSkyClamp::replace(const visibility::TexelRect& rect, int grid_width, std::span<const std::uint32_t> texels,
                              const float* blocked, const float* terrain_only, const glm::vec3* weight) {
    const std::size_t k = std::size_t(k_);
    std::vector<std::uint32_t> index;
    std::vector<float> excess;
    std::vector<glm::vec3> w;
    const std::size_t n_old = index_.size(), n_new = texels.size();
    index.reserve(n_old + n_new), excess.reserve((n_old + n_new) * k), w.reserve(n_old + n_new);
    // The new entries in ascending order (callers usually give them so already).
    std::vector<std::size_t> order(n_new);
    std::iota(order.begin(), order.end(), std::size_t(0));
    if (!std::is_sorted(texels.begin(), texels.end()))
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return texels[a] < texels[b]; });
    auto push_new = [&](std::size_t j) {
        const std::size_t e = order[j];
        index.push_back(texels[e]);
        for (std::size_t i = 0; i < k; ++i) excess.push_back(blocked[i * n_new + e] - terrain_only[i * n_new + e]);
        w.push_back(weight[e]);
    };
    // Merge the kept old entries (outside rect) with the new ones.
    std::size_t j = 0;
    for (std::size_t o = 0; o < n_old; ++o) {
        const std::uint32_t t = index_[o];
        if (rect.contains(int(t % std::uint32_t(grid_width)), int(t / std::uint32_t(grid_width)))) continue;
        while (j < n_new && texels[order[j]] < t) push_new(j++);
        index.push_back(t);
        excess.insert(excess.end(), excess_.begin() + std::ptrdiff_t(o * k), excess_.begin() + std::ptrdiff_t((o + 1) * k));
        w.push_back(weight_[o]);
    }
    while (j < n_new) push_new(j++);
    index_ = std::move(index), excess_ = std::move(excess), weight_ = std::move(w);
}

void BlockerSkyClamp::apply(const std::array<glm::vec3, 16>& light_sh, glm::vec3* out, int threads) const {
    const std::size_t n = index_.size(), k = std::size_t(k_);
    if (n == 0) return;
    constexpr int kRow = 1024;
    const int rows = int((n + kRow - 1) / kRow);
    parallel_rows(rows, threads, kRow * 16LL * 3, [&](int r0, int r1) {
        const std::size_t e = std::min(n, std::size_t(r1) * kRow);
        for (std::size_t t = std::size_t(r0) * kRow; t < e; ++t) {
            const float* d = excess_.data() + t * k;
            glm::vec3 dot(0.0f);
            for (std::size_t i = 0; i < k; ++i) dot += d[i] * light_sh[i];
            out[index_[t]] -= weight_[t] * glm::max(dot, glm::vec3(0.0f));
        }
    });
}

}  // namespace ts::render
