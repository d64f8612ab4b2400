#include "core/tiles/shade_source.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include "core/material/material.hpp"
#include "core/quality/radiance_quality.hpp"
#include "core/quality/visibility_quality.hpp"
#include "core/raster/srgb.hpp"
#include "core/render/frame_renderer.hpp"
#include "core/render/shading_state.hpp"
#include "core/render/tone_map.hpp"
#include "core/render/view_shading.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/tiles/dem_level.hpp"
#include "core/visibility/far_field_horizons.hpp"
#include "core/visibility/visibility_backend.hpp"
#include "core/visibility/window_visibility_backend.hpp"

namespace ts::tiles {
namespace {

// svf of open ground is 1; in relief valleys and gorges it falls towards ~0.5. This stretch
// spends the grey range on that interval (display-linear, then sRGB-encoded at the pixel).
constexpr float kSvfBlack = 0.55f;
// color: the exposure puts an open flat texel of albedo 1 at this (before the filmic curve),
// so a meadow (albedo ~0.15-0.2) lands near the filmic's middle grey.
constexpr double kColorExposure = 2.2;

// One grey Lambert material everywhere: relief shows form, not land cover.
render::MaterialRaster grey_materials(std::size_t n, float albedo) {
    render::MaterialRaster m;
    m.albedo_r.assign(n, albedo), m.albedo_g.assign(n, albedo), m.albedo_b.assign(n, albedo);
    m.ks.assign(n, 0.0f), m.alpha.assign(n, 1.0f);
    m.water.assign(n, 0);
    m.surface.assign(n, render::Surface::bare);
    return m;
}

// Shades a block's window from the sun by the level's terrain beyond it (empty: none).
using OuterSunShadow = std::function<void(const render::SunState&, std::vector<float>&)>;

render::RendererOptions renderer_options(const TileShading& s, ProgressBar* progress,
                                         visibility::VisibilityBackend* backend, OuterSunShadow outer_sun) {
    render::RendererOptions o;
    o.outer_sun_shadow = std::move(outer_sun);
    o.directions = s.directions;
    o.threads = s.threads;
    o.progress = progress;
    o.visibility = backend;
    return o;
}

// One frame of radiance on `grid` with `materials`; `backend` null = the CPU on `grid`.
std::vector<glm::vec3> render_frame(const terrain::HeightGrid& grid, render::MaterialRaster materials,
                                    const TileShading& s, ProgressBar* progress,
                                    visibility::VisibilityBackend* backend = nullptr, OuterSunShadow outer_sun = {}) {
    render::NormalField normals = render::terrain_normals(grid, s.threads);
    auto state = render::compute_shading_state(grid, std::move(materials), std::move(normals),
                                               renderer_options(s, progress, backend, std::move(outer_sun)));
    const render::ViewShading view = render::compute_view_shading(*state, {});
    render::FrameRenderer frame(*state, view);
    const render::SunState sun{s.sun_azimuth_deg, s.sun_elevation_deg};
    const auto sky = light::make_sky(s.sky, render::sun_direction(sun));
    std::vector<glm::vec3> radiance;
    frame.render(*sky, sun, radiance);
    return radiance;
}

// Luminance of an open flat texel of albedo 1 under the same light, at the grid's spacing: the
// reference that makes relief and color independent of the sky's absolute units.
double flat_reference(const terrain::HeightGrid& like, const TileShading& s) {
    constexpr int n = 32;
    const std::vector<float> z(std::size_t(n) * n, 0.0f);
    const std::size_t mid_row = std::size_t(like.height / 2);
    const terrain::HeightGrid flat = terrain::HeightGrid::uniform(n, n, z, like.dx_m[mid_row], like.dy_m[mid_row]);
    TileShading quiet = s;
    quiet.threads = 1;
    const auto radiance = render_frame(flat, grey_materials(z.size(), 1.0f), quiet, nullptr);
    return render::luminance(radiance[std::size_t(n / 2) * n + n / 2]);
}

// A rectangle of the level: a block's core or window.
using Rect = visibility::ReceiverWindow;

// A window of a grid as a grid of its own, its heights (and void mask) copied into `z`/`voids`.
terrain::HeightGrid window_grid(const terrain::HeightGrid& g, const Rect& w, std::vector<float>& z,
                                std::vector<std::uint8_t>& voids) {
    z.resize(std::size_t(w.width) * std::size_t(w.height));
    voids.assign(g.void_mask.empty() ? 0 : z.size(), 0);
    for (int r = 0; r < w.height; ++r) {
        const std::size_t from = g.index(w.col0, w.row0 + r), to = std::size_t(r) * std::size_t(w.width);
        std::copy_n(g.z.data() + from, w.width, z.data() + to);
        if (!voids.empty()) std::copy_n(g.void_mask.data() + from, w.width, voids.data() + to);
    }
    terrain::HeightGrid out;
    out.width = w.width, out.height = w.height;
    out.z = z;
    out.void_mask = voids;
    out.dx_m.assign(g.dx_m.begin() + w.row0, g.dx_m.begin() + w.row0 + w.height);
    out.dy_m.assign(g.dy_m.begin() + w.row0, g.dy_m.begin() + w.row0 + w.height);
    return out;
}

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
    ShadeSource out;
    out.level = level;
    out.width = lvl.width, out.height = lvl.height;
    out.vertical_scale = vertical_scale;
    const std::size_t n = lvl.z.size();
    if (!uses_visibility(s.style)) {
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
    if (s.style != TileStyle::color) {
        // Only the colours need the true heights (a snow line does not move with the
        // exaggeration): free them for the rest.
        std::vector<float>().swap(lvl.z);
        true_grid.z = {};
    }
    out.channels = s.style == TileStyle::color ? 3 : 1;
    out.values.resize(std::size_t(out.channels) * n);
    const double flat = s.style == TileStyle::svf ? 1.0 : flat_reference(grid, s);

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
    std::vector<float> wz, wtrue;
    std::vector<std::uint8_t> wvoids, wtrue_voids;
    // --max-error: each block's directions from its own roughness (its core, heights as
    // shaded), the picture's predicted RMS under the bound at the least cost.
    std::vector<int> block_directions(blocks.size(), s.directions);
    if (s.max_error > 0 && !whole && s.style != TileStyle::svf) {
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
        // svf sweeps its core's horizons over the whole level: no halo.
        const int halo = whole || (s.style == TileStyle::svf && !far) ? 0 : block_halo;
        Rect w;
        w.col0 = std::max(0, core.col0 - halo), w.row0 = std::max(0, core.row0 - halo);
        w.width = std::min(grid.width, core.col0 + core.width + halo) - w.col0;
        w.height = std::min(grid.height, core.row0 + core.height + halo) - w.row0;
        std::vector<float> values;  // per window texel, `channels` each
        if (s.style == TileStyle::svf) {
            visibility::VisibilityRequest request;
            request.horizon.directions = s.directions;
            request.horizon.threads = s.threads;
            request.horizon.progress = whole ? progress : nullptr;
            request.horizon.window = {w.col0, w.row0, w.width, w.height};
            request.svf = true;
            visibility::VisibilityResult result;
            if (far) {
                std::vector<float> sz;
                std::vector<std::uint8_t> svoids;
                const terrain::HeightGrid g = window_grid(grid, w, sz, svoids);
                result = visibility::WindowFarFieldVisibility(w, core, *far).compute(g, request);
            } else {
                result = visibility::make_cpu_visibility_backend()->compute(grid, request);
            }
            values.resize(result.svf.size());
            for (std::size_t k = 0; k < values.size(); ++k) {
                const float v = std::isnan(result.svf[k]) ? 1.0f : result.svf[k];
                values[k] = raster::srgb_eotf(std::clamp((v - kSvfBlack) / (1.0f - kSvfBlack), 0.0f, 1.0f));
            }
        } else {
            std::unique_ptr<visibility::WindowFarFieldVisibility> backend;
            terrain::HeightGrid g = grid, tg = true_grid;
            OuterSunShadow outer_sun;
            if (!whole) {
                g = window_grid(grid, w, wz, wvoids);
                if (s.style == TileStyle::color) tg = window_grid(true_grid, w, wtrue, wtrue_voids);
                backend = far ? std::make_unique<visibility::WindowFarFieldVisibility>(w, core, *far)
                              : std::make_unique<visibility::WindowFarFieldVisibility>(w, core, grid);
            }
            // The far field shades the core from the sun past the halo (the sweep's shadows end there).
            if (far) outer_sun = visibility::far_field_sun_shadow(w, core, *far, g);
            const std::size_t m = std::size_t(w.width) * std::size_t(w.height);
            if (s.style == TileStyle::relief) {
                const auto radiance = render_frame(g, grey_materials(m, 1.0f), bs, whole ? progress : nullptr, backend.get(), outer_sun);
                values.resize(m);
                for (std::size_t k = 0; k < m; ++k)
                    values[k] = relief_grey(render::luminance(radiance[k]) / flat, s.relief_contrast);
            } else {
                // Land cover from the true heights and slopes; the light on the exaggerated form.
                const render::NormalField true_normals = render::terrain_normals(tg, s.threads);
                const auto radiance = render_frame(g, render::rule_materials(tg, true_normals), bs,
                                                   whole ? progress : nullptr, backend.get(), outer_sun);
                const float scale = float(kColorExposure / flat);
                values.resize(3 * m);
                for (std::size_t k = 0; k < m; ++k)
                    for (int c = 0; c < 3; ++c) values[3 * k + std::size_t(c)] = radiance[k][c] * scale;
            }
        }
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
