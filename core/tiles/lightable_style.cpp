// `lightable`: data tiles a browser relights for any instant (docs/web-map.md). Per source texel
// it keeps what `relief` and `color` light a texel from, except the light itself: the unit
// normal, the land's albedo (the job's palette, as `color`), the diffuse transfer T_d of bands
// 0..2 (the band correction zeroes band 3) and the exact horizons at the job's light
// directions; lightable_tile.hpp encodes them per tile.
#include <cmath>

#include "core/material/palette_materials.hpp"
#include "core/render/shading_state.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/tiles/block_shading.hpp"
#include "core/tiles/lightable_tile.hpp"
#include "core/tiles/tile_style.hpp"

namespace ts::tiles {
namespace {

class LightableStyle final : public TileStyle {
public:
    std::string_view name() const override { return "lightable"; }
    bool uses_visibility() const override { return true; }
    bool data_tile() const override { return true; }
    int channels(const TileShading& s) const override { return lightable_channels(s.light_directions); }
    bool takes_relief_contrast() const override { return true; }
    bool needs_true_heights() const override { return true; }
    bool colours_land() const override { return true; }
    std::vector<float> shade_block(const BlockShading& b) const override {
        const int d_count = b.shading.light_directions;
        const int ch = lightable_channels(d_count);
        std::vector<float> values;
        // The relief's own state of the window: the same normals and transfer as its frame.
        const StateInspector keep = [&](const render::ShadingState& state) {
            const std::size_t n = state.texels();
            values.assign(n * std::size_t(ch), 0.0f);
            const render::NormalField& nf = state.normals();
            const std::vector<float>& t = state.kept_diffuse_transfer();
            const std::vector<float>& bounce = state.bounce_transfer();  // empty: none
            for (std::size_t k = 0; k < n; ++k) {
                float* v = values.data() + k * std::size_t(ch);
                v[kLightNormal] = nf.x[k], v[kLightNormal + 1] = nf.y[k], v[kLightNormal + 2] = nf.z[k];
                for (int i = 0; i < kLightTransfer; ++i) v[kLightTransferAt + i] = t[std::size_t(i) * n + k];
                for (int i = 0; i < kLightBounce; ++i) {
                    const float tb = bounce.empty() ? 0.0f : bounce[std::size_t(i) * n + k];
                    v[kLightBounceAt + i] = tb == tb ? tb : 0.0f;
                }
            }
        };
        // The land's colours as `color` finds them: from the true heights (and slopes, for snow).
        const int threads = b.shading.threads;
        const render::ColorDesign& colors = b.shading.colors;
        render::MaterialRaster land;
        render_block(
            b,
            [&](const terrain::HeightGrid&, const terrain::HeightGrid& tg) {
                land = render::palette_materials(tg, render::terrain_normals(tg, threads), colors);
                return land;
            },
            true, &keep);
        for (std::size_t k = 0; k < land.albedo_r.size(); ++k) {
            float* v = values.data() + k * std::size_t(ch);
            v[kLightAlbedoAt] = land.albedo_r[k], v[kLightAlbedoAt + 1] = land.albedo_g[k], v[kLightAlbedoAt + 2] = land.albedo_b[k];
        }
        // The exact horizons at the light directions, through the far field as the sky's.
        visibility::VisibilityRequest request;
        request.horizon.directions = d_count;
        request.horizon.threads = b.shading.threads;
        // As the sun's own sweep marches its near field (sun_visibility.hpp): shadow rims.
        request.horizon.exact_near_field_texels = 8.0;
        std::vector<float> wz;
        std::vector<std::uint8_t> wvoids;
        const terrain::HeightGrid g = b.far ? window_grid(b.grid, b.window, wz, wvoids) : terrain::HeightGrid{};
        const visibility::VisibilityResult r = block_visibility(b, request, g);
        const std::size_t n = r.horizons.texels();
        for (int d = 0; d < d_count; ++d) {
            // Stored by user azimuth d * 360 / D clockwise from north; internal index i has
            // azimuth 90 - 360 i / D.
            const int i = ((d_count / 4 - d) % d_count + d_count) % d_count;
            const float* plane = r.horizons.plane(i);
            for (std::size_t k = 0; k < n; ++k) values[k * std::size_t(ch) + std::size_t(kLightHorizonAt + d)] = plane[k];
        }
        return values;
    }
};

}  // namespace

const TileStyle& lightable_tile_style() {
    static const LightableStyle style;
    return style;
}

}  // namespace ts::tiles
