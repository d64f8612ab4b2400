// `color`: the land colours of the job's palette (by the true heights; snow above its snow line)
// under the sun and sky on the exaggerated form; linear RGB exposed for the filmic curve (render --view
// map's look, with a fixed exposure).
#include "core/material/palette_materials.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/tiles/block_shading.hpp"
#include "core/tiles/tile_style.hpp"

namespace ts::tiles {
namespace {

class ColorStyle final : public TileStyle {
public:
    std::string_view name() const override { return "color"; }
    bool uses_visibility() const override { return true; }
    int channels() const override { return 3; }
    bool filmic() const override { return true; }
    bool needs_true_heights() const override { return true; }
    bool relative_to_flat() const override { return true; }
    bool takes_max_error() const override { return true; }
    bool colours_land() const override { return true; }
    std::vector<float> shade_block(const BlockShading& b) const override {
        const int threads = b.shading.threads;
        const render::ColorDesign& colors = b.shading.colors;
        // Colours from the true heights (and slopes, for snow); the light on the exaggerated form.
        const auto radiance = render_block(
            b,
            [threads, &colors](const terrain::HeightGrid&, const terrain::HeightGrid& tg) {
                const render::NormalField true_normals = render::terrain_normals(tg, threads);
                return render::palette_materials(tg, true_normals, colors);
            },
            true);
        const float scale = float(kColorExposure / b.flat);
        std::vector<float> values(3 * radiance.size());
        for (std::size_t k = 0; k < radiance.size(); ++k)
            for (int c = 0; c < 3; ++c) values[3 * k + std::size_t(c)] = radiance[k][c] * scale;
        return values;
    }
};

}  // namespace

const TileStyle& color_tile_style() {
    static const ColorStyle style;
    return style;
}

}  // namespace ts::tiles
