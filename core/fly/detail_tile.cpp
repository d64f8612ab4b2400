#include "core/fly/detail_tile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/fly/radiance_pack.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/visibility/far_field_horizons.hpp"
#include "core/visibility/window_visibility_backend.hpp"

namespace ts::fly {
namespace {


}  // namespace

DetailTileLayout detail_tile_layout(const TerrainOverview& o, int patch_quads) {
    DetailTileLayout l;
    l.width = o.width, l.height = o.height;
    l.levels_below = o.cdlod.stored_level;
    l.patch_quads = patch_quads;
    l.tile_texels = std::max(256, l.levels_below > 0 ? patch_quads << (l.levels_below - 1) : 256);
    l.tiles_x = (o.width - 1 + l.tile_texels - 1) / l.tile_texels;
    l.tiles_y = (o.height - 1 + l.tile_texels - 1) / l.tile_texels;
    return l;
}

DetailTileKey tile_of_node(const DetailTileLayout& l, int level, int ix, int iy) {
    const int per = l.tile_texels / (l.patch_quads << level);
    return {ix / per, iy / per};
}

float overview_height(const TerrainOverview& o, double col, double row) {
    const double s = double(1 << o.level);
    const double u = std::clamp(col / s, 0.0, double(o.points.width - 1));
    const double v = std::clamp(row / s, 0.0, double(o.points.height - 1));
    const int i = std::min(int(u), o.points.width - 2), j = std::min(int(v), o.points.height - 2);
    const double fu = u - i, fv = v - j;
    const double top = o.points.at(i, j) + fu * (o.points.at(i + 1, j) - o.points.at(i, j));
    const double bottom = o.points.at(i, j + 1) + fu * (o.points.at(i + 1, j + 1) - o.points.at(i, j + 1));
    return float(top + fv * (bottom - top));
}

DetailTile::DetailTile(DetailTileKey key, const DetailTileLayout& layout, const dem::DemSource& source,
                       const TerrainOverview& overview, const visibility::FarField& far,
                       const DetailShadingOptions& options)
    : key_(key), layout_(layout) {
    const int T = layout.tile_texels;
    col0_ = key.tx * T, row0_ = key.ty * T;
    samples_x_ = std::min(T, layout.width - 1 - col0_) + 1;
    samples_y_ = std::min(T, layout.height - 1 - row0_) + 1;
    window_col0_ = std::max(0, col0_ - options.halo);
    window_row0_ = std::max(0, row0_ - options.halo);
    const int wc1 = std::min(layout.width, col0_ + samples_x_ + options.halo);
    const int wr1 = std::min(layout.height, row0_ + samples_y_ + options.halo);
    window_ = std::make_unique<dem::Dem>();
    dem::Dem& w = *window_;
    w.width = wc1 - window_col0_, w.height = wr1 - window_row0_;
    source.read(window_col0_, window_row0_, w.width, w.height, w.z, &w.void_mask);
    for (int r = 0; r < w.height; ++r)
        for (int c = 0; c < w.width; ++c) {
            float& z = w.z[w.index(c, r)];
            if (std::isnan(z)) z = overview_height(overview, window_col0_ + c, window_row0_ + r);
        }
    w.georef = source.layout().georef.window(window_col0_, window_row0_, w.width, w.height);
    w.vertical_datum = source.layout().vertical_datum;
    w.source = source.layout().source;

    heights_.resize(std::size_t(samples_x_) * std::size_t(samples_y_));
    for (int r = 0; r < samples_y_; ++r)
        for (int c = 0; c < samples_x_; ++c)
            heights_[std::size_t(r) * std::size_t(samples_x_) + std::size_t(c)] =
                w.at(col0_ - window_col0_ + c, row0_ - window_row0_ + r);
    // Node ranges of the levels below the overview's, tile-local.
    const int n = layout.patch_quads;
    node_z_.resize(std::size_t(layout.levels_below));
    for (int k = 0; k < layout.levels_below; ++k) {
        const int size = n << k;
        const int nx = std::max(1, (samples_x_ - 1 + size - 1) / size), ny = std::max(1, (samples_y_ - 1 + size - 1) / size);
        nodes_x_.push_back(nx);
        auto& level = node_z_[std::size_t(k)];
        level.assign(std::size_t(nx) * std::size_t(ny), glm::vec2(std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()));
        for (int iy = 0; iy < ny; ++iy)
            for (int ix = 0; ix < nx; ++ix) {
                glm::vec2& b = level[std::size_t(iy) * std::size_t(nx) + std::size_t(ix)];
                for (int r = iy * size; r <= std::min((iy + 1) * size, samples_y_ - 1); ++r)
                    for (int c = ix * size; c <= std::min((ix + 1) * size, samples_x_ - 1); ++c) {
                        const float z = heights_[std::size_t(r) * std::size_t(samples_x_) + std::size_t(c)];
                        b.x = std::min(b.x, z), b.y = std::max(b.y, z);
                    }
            }
    }

    render::SceneOptions so;
    so.view = render::ViewKind::map;
    so.sky = light::parse_sky_options(options.sky);
    // The palette's percent stops on the overview's heights, unless fitted already (the cache
    // fits once): every tile colours a height alike (a window's own range would not).
    so.colors = render::fit_colors(options.colors, overview.points);
    so.renderer.directions = options.directions;
    so.renderer.bounce = options.bounce;
    so.renderer.sky_light = options.sky_light;
    so.renderer.threads = options.threads;
    so.renderer.keep_sun_horizon = options.sun_horizon;  // the fragments place shadow edges inside texels
    const visibility::ReceiverWindow window{window_col0_, window_row0_, w.width, w.height};
    const visibility::ReceiverWindow core{col0_, row0_, samples_x_, samples_y_};
    backend_ = visibility::make_window_far_field_visibility(window, core, far);
    so.renderer.visibility = backend_.get();
    so.renderer.outer_sun_shadow = visibility::far_field_sun_shadow(window, core, far, terrain::metric_view(w));
    scene_ = std::make_unique<render::Scene>(w, so);
    open_sky_ = scene_->open_sky_fraction();
}

DetailTile::~DetailTile() = default;

glm::vec2 DetailTile::node_z(int level, int ix, int iy) const {
    const int size = layout_.patch_quads << level;
    const int lx = ix - col0_ / size, ly = iy - row0_ / size;
    return node_z_[std::size_t(level)][std::size_t(ly) * std::size_t(nodes_x_[std::size_t(level)]) + std::size_t(lx)];
}

void DetailTile::light(const render::SunState& sun, std::vector<std::uint32_t>& radiance,
                       std::vector<std::uint32_t>& sun_light) {
    scene_->render(sun, image_);
    const render::TexelSunSplitter split(*scene_, sun, *scene_->last_sky());
    const std::size_t n = std::size_t(samples_x_) * std::size_t(samples_y_);
    radiance.resize(2 * n), sun_light.resize(4 * n);
    for (int r = 0; r < samples_y_; ++r)
        for (int c = 0; c < samples_x_; ++c) {
            const std::size_t from = window_->index(col0_ - window_col0_ + c, row0_ - window_row0_ + r);
            const std::size_t to = std::size_t(r) * std::size_t(samples_x_) + std::size_t(c);
            const render::TexelSunLight l = split(from, image_.rgb[from]);
            pack_radiance(l.rest, 0.0f, &radiance[2 * to]);
            pack_sun_light(l.sun_albedo, open_sky_[from], l.normal, l.horizon_above_sun, &sun_light[4 * to]);
        }
}

std::size_t detail_tile_bytes(int tile_texels, int halo) {
    const std::size_t window = std::size_t(tile_texels + 1 + 2 * halo);
    const std::size_t samples = std::size_t(tile_texels + 1) * std::size_t(tile_texels + 1);
    // Per window texel: the state, heights, fill flag, frame and the frame's sun horizon; per
    // sample: height, radiance and sun light, with their upload copies.
    return window * window * (200 + 2 * sizeof(float) + 1 + sizeof(glm::vec3) + sizeof(float)) +
           samples * (4 + 8 + 16) * 2;
}

}  // namespace ts::fly
