// `svf`: the sky view factor, grey, stretched over the range relief spans.
#include <algorithm>
#include <cmath>

#include "core/raster/srgb.hpp"
#include "core/tiles/block_shading.hpp"
#include "core/tiles/svf_stretch.hpp"
#include "core/tiles/tile_style.hpp"

namespace ts::tiles {
namespace {

class SvfStyle final : public TileStyle {
public:
    std::string_view name() const override { return "svf"; }
    bool uses_visibility() const override { return true; }
    // Without a far field a block's horizons are swept over the whole level: no halo.
    bool halo_without_far_field() const override { return false; }
    std::vector<float> shade_block(const BlockShading& b) const override {
        std::vector<float> values = block_svf(b);
        for (float& value : values) {
            const float v = std::isnan(value) ? 1.0f : value;
            value = raster::srgb_eotf(std::clamp((v - kSvfBlack) / (1.0f - kSvfBlack), 0.0f, 1.0f));
        }
        return values;
    }
};

}  // namespace

const TileStyle& svf_tile_style() {
    static const SvfStyle style;
    return style;
}

}  // namespace ts::tiles
