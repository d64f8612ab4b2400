// `insolation`: one quantity of the clear-sky solar irradiation over a range of days (global by
// default, kWh/m2; or hours of direct sun) through the inferno colour ramp, from each block's
// exact horizons, normals and latitudes and the sun tables the job built once
// (core/solar, tile_insolation.hpp). Its heights are the true ones: an exaggerated relief would
// shade the sun out of valleys it reaches.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/raster/colour_ramp.hpp"
#include "core/raster/srgb.hpp"
#include "core/solar/insolation_map.hpp"
#include "core/solar/terrain_reflection.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/tiles/block_shading.hpp"
#include "core/tiles/tile_insolation.hpp"
#include "core/tiles/tile_style.hpp"

namespace ts::tiles {
namespace {

class InsolationStyle final : public TileStyle {
public:
    std::string_view name() const override { return "insolation"; }
    bool uses_visibility() const override { return true; }
    int channels() const override { return 3; }
    bool needs_latitudes() const override { return true; }
    // A block's window keeps its halo even when its horizons are swept over the whole level:
    // the normals at the core's edges need the texels beyond it.
    std::vector<float> shade_block(const BlockShading& b) const override {
        const TileInsolation* ins = b.shading.insolation.get();
        // The job sets them once the DEM is read (the command's set_tile_insolation).
        if (!ins || !ins->model || !b.latitude) throw std::logic_error("insolation tiles: no sun tables or latitudes");
        const Rect& w = b.window;
        // The window as a grid of its own: its horizons, normals and latitudes.
        std::vector<float> wz, lat(std::size_t(w.width) * std::size_t(w.height));
        std::vector<std::uint8_t> wvoids;
        const terrain::HeightGrid g = window_grid(b.grid, w, wz, wvoids);
        const int level_width = b.grid.width;
        for (int r = 0; r < w.height; ++r)
            for (int c = 0; c < w.width; ++c)
                lat[std::size_t(r) * std::size_t(w.width) + std::size_t(c)] =
                    (*b.latitude)[std::size_t(w.row0 + r) * std::size_t(level_width) + std::size_t(w.col0 + c)];
        visibility::VisibilityRequest request;
        request.horizon.directions = b.shading.directions;
        request.horizon.threads = b.shading.threads;
        request.horizon.progress = b.progress;
        const visibility::VisibilityResult vis = block_visibility(b, request, g);
        const render::NormalField normals = render::terrain_normals(g, b.shading.threads);
        solar::InsolationMap map = solar::integrate_insolation(*ins->model, g, vis.horizons, normals, lat);
        // The reflection's gather looks no farther than the halo (less the bilinear cell and a
        // rounding texel), so a core texel sees the same terrain in its block as in the whole level.
        solar::TerrainReflectionSettings reflection = ins->reflection;
        reflection.radius_texels =
            std::min(reflection.radius_texels, std::max(1.0, double(b.shading.block_halo_texels - 2)));
        solar::apply_terrain_reflection(map, g, vis.horizons, normals, ins->model->settings().albedo, reflection,
                                        b.shading.threads);

        const std::size_t n = lat.size();
        std::vector<float> values(3 * n, std::numeric_limits<float>::quiet_NaN());
        const float scale = 1.0f / std::max(1e-6f, ins->hi - ins->lo);
        for (std::size_t k = 0; k < n; ++k) {
            float v = 0;
            for (int p = 0; p < map.periods; ++p) v += map.band(p, ins->quantity)[k];
            if (std::isnan(v)) continue;  // void, or the halo a far field leaves to its core
            std::uint8_t rgb[3];
            raster::inferno_ramp((v - ins->lo) * scale, rgb);
            // Display-linear, as the tiles' sRGB encoding expects (tile_renderer.cpp).
            for (int c = 0; c < 3; ++c) values[3 * k + std::size_t(c)] = raster::srgb_eotf(rgb[c] / 255.0f);
        }
        return values;
    }
};

}  // namespace

const TileStyle& insolation_tile_style() {
    static const InsolationStyle style;
    return style;
}

}  // namespace ts::tiles
