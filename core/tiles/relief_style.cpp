// `relief`: grey shaded relief, the sun with cast shadows and the sky through log-SH visibility on
// a grey Lambert ground, relative to open flat ground under the same light (relief_grey,
// shade_source.hpp); display-linear 0..1.
#include "core/render/tone_map.hpp"
#include "core/tiles/block_shading.hpp"
#include "core/tiles/shade_source.hpp"
#include "core/tiles/tile_style.hpp"

namespace ts::tiles {
namespace {

class ReliefStyle final : public TileStyle {
public:
    std::string_view name() const override { return "relief"; }
    bool uses_visibility() const override { return true; }
    bool relative_to_flat() const override { return true; }
    bool takes_max_error() const override { return true; }
    bool takes_relief_contrast() const override { return true; }
    std::vector<float> shade_block(const BlockShading& b) const override {
        // Relief is relative to open flat ground, so the albedo only sets how much light bounces:
        // `--colors grey`'s, as a path tracer's uniform grey terrain.
        const auto radiance = render_block(
            b,
            [](const terrain::HeightGrid& g, const terrain::HeightGrid&) { return grey_materials(g.z.size(), kReliefAlbedo); },
            false);
        std::vector<float> values(radiance.size());
        for (std::size_t k = 0; k < values.size(); ++k)
            values[k] = relief_grey(render::luminance(radiance[k]) / (b.flat * kReliefAlbedo), b.shading.relief_contrast);
        return values;
    }
};

}  // namespace

const TileStyle& relief_tile_style() {
    static const ReliefStyle style;
    return style;
}

}  // namespace ts::tiles
