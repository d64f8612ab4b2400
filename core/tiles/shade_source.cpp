#include "core/tiles/shade_source.hpp"

#include <algorithm>
#include <memory>

#include "core/quality/radiance_quality.hpp"
#include "core/solar/insolation_map.hpp"
#include "core/quality/visibility_quality.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/terrain/isotropic_rows.hpp"
#include "core/tiles/block_shading.hpp"
#include "core/tiles/dem_level.hpp"
#include "core/visibility/far_field_horizons.hpp"

namespace ts::tiles {
namespace {

// The blocks a level is shaded in: one (the whole level) when it fits.
std::vector<Rect> level_blocks(int width, int height, int block) {
    if (block <= 0 || (width <= block && height <= block)) return {{0, 0, width, height}};
    std::vector<Rect> out;
    for (int r = 0; r < height; r += block)
        for (int c = 0; c < width; c += block) out.push_back({c, r, std::min(block, width - c), std::min(block, height - r)});
    return out;
}

}  // namespace

ShadeSource make_shade_source(const dem::Dem& dem, const TileShading& s, int level, double vertical_scale,
                              ProgressBar* progress) {
    dem::Dem lvl = dem_level(dem, level, s.threads);
    // No streaks along the meridians near the poles: rows of narrow texels averaged to square ones.
    terrain::make_rows_isotropic(terrain::metric_view(lvl), lvl.z);
    ShadeSource out;
    out.level = level;
    out.width = lvl.width, out.height = lvl.height;
    out.vertical_scale = vertical_scale;
    const TileStyle& style = *s.style;
    const std::size_t n = lvl.z.size();
    if (!style.uses_visibility()) {
        out.values = std::move(lvl.z);
        return out;
    }
    // The heights as shaded: exaggerated (the metric spacing stays true).
    std::vector<float> scaled(n);
    for (std::size_t k = 0; k < n; ++k) scaled[k] = float(lvl.z[k] * vertical_scale);
    terrain::HeightGrid grid = terrain::metric_view(lvl);
    grid.z = scaled;
    terrain::HeightGrid true_grid = grid;
    true_grid.z = lvl.z;
    if (!style.needs_true_heights()) {
        // Only the colours need the true heights (a snow line does not move with the
        // exaggeration): free them for the rest.
        std::vector<float>().swap(lvl.z);
        true_grid.z = {};
    }
    out.channels = style.channels(s);
    out.filmic = style.filmic();
    out.values.resize(std::size_t(out.channels) * n);
    const double flat = style.relative_to_flat() ? flat_reference(grid, s) : 1.0;
    const std::vector<float> latitude =
        style.needs_latitudes() ? solar::texel_latitudes(lvl.georef, s.threads) : std::vector<float>();

    const std::vector<Rect> blocks = level_blocks(grid.width, grid.height, s.block_texels);
    const bool whole = blocks.size() == 1;
    // Terrain beyond a block's halo, for every block of the level (built once, a few MB).
    std::unique_ptr<visibility::FarField> far;
    const int block_halo = std::max(1, s.block_halo_texels);
    if (!whole && s.far_field != FarFieldMethod::exact) {
        visibility::FarFieldOptions fo;
        fo.start_texels = block_halo;
        fo.samples_per_octave = far_field_samples_per_octave(s.far_field);
        fo.threads = s.threads;
        far = std::make_unique<visibility::FarField>(grid, fo);
    }
    // --max-error: each block's directions from its own roughness (its core, heights as
    // shaded), the picture's predicted RMS under the bound at the least cost.
    std::vector<int> block_directions(blocks.size(), s.directions);
    if (s.max_error > 0 && !whole && style.takes_max_error()) {
        std::vector<double> roughness, weight;
        for (const Rect& b : blocks) {
            roughness.push_back(quality::mean_tan_slope(grid, b.col0, b.row0, b.width, b.height));
            weight.push_back(double(b.width) * double(b.height));
        }
        const quality::RegionChoice rc =
            quality::choose_radiance_per_region(s.max_error, roughness, weight, s.sun_elevation_deg, false);
        for (std::size_t b = 0; b < blocks.size(); ++b)
            block_directions[b] = quality::radiance_settings()[std::size_t(rc.setting[b])].directions;
    }
    for (std::size_t bi = 0; bi < blocks.size(); ++bi) {
        const Rect& core = blocks[bi];
        TileShading bs = s;
        bs.directions = block_directions[bi];
        ++out.blocks_by_directions[bs.directions];
        // The window each block is shaded on: its core grown by the halo (sun shadows, normals
        // at the edge, the near field of the sky), clamped to the level. Without a far field
        // a style may sweep its core's horizons over the whole level instead: no halo.
        const int halo = whole || (!style.halo_without_far_field() && !far) ? 0 : block_halo;
        Rect w;
        w.col0 = std::max(0, core.col0 - halo), w.row0 = std::max(0, core.row0 - halo);
        w.width = std::min(grid.width, core.col0 + core.width + halo) - w.col0;
        w.height = std::min(grid.height, core.row0 + core.height + halo) - w.row0;
        const BlockShading block{grid, true_grid, w, core, whole, far.get(), bs, flat, whole ? progress : nullptr,
                                 style.needs_latitudes() ? &latitude : nullptr};
        const std::vector<float> values = style.shade_block(block);  // per window texel, `channels` each
        // The core's rows into the level's raster.
        const std::size_t ch = std::size_t(out.channels);
        for (int r = 0; r < core.height; ++r) {
            const float* from = values.data() + (std::size_t(core.row0 - w.row0 + r) * std::size_t(w.width) +
                                                 std::size_t(core.col0 - w.col0)) * ch;
            float* to = out.values.data() + (std::size_t(core.row0 + r) * std::size_t(grid.width) + std::size_t(core.col0)) * ch;
            std::copy_n(from, std::size_t(core.width) * ch, to);
        }
    }
    return out;
}

}  // namespace ts::tiles
