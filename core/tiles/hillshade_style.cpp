// `hillshade`: Horn, as gdaldem hillshade on the tile's pixels (tile_horn.hpp).
#include "core/tiles/tile_horn.hpp"
#include "core/tiles/tile_style.hpp"

namespace ts::tiles {
namespace {

class HillshadeStyle final : public TileStyle {
public:
    std::string_view name() const override { return "hillshade"; }
    bool uses_visibility() const override { return false; }
    void shade_tile(const TileFrame& f, const std::vector<float>& heights, double vertical_scale, const HornLight& light,
                    const std::uint8_t* covered, std::uint8_t* out) const override {
        horn_hillshade(f, heights, vertical_scale, light, covered, out);
    }
};

}  // namespace

const TileStyle& hillshade_tile_style() {
    static const HillshadeStyle style;
    return style;
}

}  // namespace ts::tiles
