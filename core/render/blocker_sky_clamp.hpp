#pragma once
// A mesh blocker only removes light. Its order-4 log-SH caps ring, and the exponential
// amplifies the positive lobe: beside a deep contact shadow the blocked diffuse transfer T_b can
// shade a texel brighter than the terrain's alone, T_t (docs/blockers.md, "The bright rim").
// So each frame's sky term of a texel the blockers changed is bounded by its terrain-only one,
// channel by channel (blocked_sky_term):
//   sky_t = min(<T_b, L>, <T_t, L>)
// Kept per such texel: D = T_b - T_t (the coefficients that carry light) and the weight the
// frame's diffuse pass multiplies the sky term by (the albedo on the fused CPU path, 1 where the
// pass returns the sky term alone); after that pass,
//   out_t -= w_t * max(0, <D_t, L>)
// which is w_t * blocked_sky_term(<T_b, L>, <T_t, L>) in place of w_t * <T_b, L>. Cost: one
// K-term dot product per channel per changed texel and frame.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/visibility/blocker_footprint.hpp"

namespace ts::render {

// The one definition of the bound, for the renderer and for what measures it (bench blockers).
inline double blocked_sky_term(double with_blockers, double terrain_only) {
    return std::min(with_blockers, terrain_only);
}

class BlockerSkyClamp {
public:
    // coefficients: 9 (band 3 zeroed by the band correction) or 16.
    explicit BlockerSkyClamp(int coefficients);

    // Drops the texels inside `rect` (of a grid `grid_width` texels wide), then adds `texels`
    // (all inside `rect`, grid indices) with their blocked and terrain-only transfers
    // ([16][texels.size()], as transfer_vectors writes them) and weights.
    void replace(const visibility::TexelRect& rect, int grid_width, std::span<const std::uint32_t> texels,
                 const float* blocked, const float* terrain_only, const glm::vec3* weight);

    // The formula above on `out` (grid texels).
    void apply(const std::array<glm::vec3, 16>& light_sh, glm::vec3* out, int threads) const;

    std::size_t texels() const { return index_.size(); }
    int coefficients() const { return k_; }
    // The grid indices of the texels kept, ascending.
    const std::vector<std::uint32_t>& index() const { return index_; }

private:
    int k_;
    std::vector<std::uint32_t> index_;  // ascending
    std::vector<float> excess_;         // [texel][k_]: D
    std::vector<glm::vec3> weight_;
};

}  // namespace ts::render
