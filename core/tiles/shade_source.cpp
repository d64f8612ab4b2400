#include "core/tiles/shade_source.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/material/material.hpp"
#include "core/raster/srgb.hpp"
#include "core/render/frame_renderer.hpp"
#include "core/render/shading_state.hpp"
#include "core/render/tone_map.hpp"
#include "core/render/view_shading.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/tiles/dem_level.hpp"
#include "core/visibility/visibility_backend.hpp"

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

render::RendererOptions renderer_options(const TileShading& s, ProgressBar* progress) {
    render::RendererOptions o;
    o.directions = s.directions;
    o.threads = s.threads;
    o.progress = progress;
    return o;
}

// One frame of radiance on `grid` with `materials`.
std::vector<glm::vec3> render_frame(const terrain::HeightGrid& grid, render::MaterialRaster materials,
                                    const TileShading& s, ProgressBar* progress) {
    render::NormalField normals = render::terrain_normals(grid, s.threads);
    auto state = render::compute_shading_state(grid, std::move(materials), std::move(normals), renderer_options(s, progress));
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

}  // namespace

ShadeSource make_shade_source(const dem::Dem& dem, const TileShading& s, int level, double vertical_scale,
                              ProgressBar* progress) {
    const dem::Dem lvl = dem_level(dem, level, s.threads);
    ShadeSource out;
    out.level = level;
    out.width = lvl.width, out.height = lvl.height;
    out.vertical_scale = vertical_scale;
    const std::size_t n = lvl.z.size();
    if (!uses_visibility(s.style)) {
        out.values = lvl.z;
        return out;
    }
    // The heights as shaded: exaggerated (the metric spacing stays true).
    const terrain::HeightGrid true_grid = terrain::metric_view(lvl);
    std::vector<float> scaled(n);
    for (std::size_t k = 0; k < n; ++k) scaled[k] = float(lvl.z[k] * vertical_scale);
    terrain::HeightGrid grid = true_grid;
    grid.z = scaled;

    switch (s.style) {
        case TileStyle::relief: {
            const auto radiance = render_frame(grid, grey_materials(n, 1.0f), s, progress);
            const double flat = flat_reference(grid, s);
            out.values.resize(n);
            for (std::size_t k = 0; k < n; ++k)
                out.values[k] = std::clamp(float(kReliefFlatGrey * render::luminance(radiance[k]) / flat), 0.0f, 1.0f);
            break;
        }
        case TileStyle::svf: {
            visibility::VisibilityRequest request;
            request.horizon.directions = s.directions;
            request.horizon.threads = s.threads;
            request.horizon.progress = progress;
            request.svf = true;
            const auto result = visibility::make_cpu_visibility_backend()->compute(grid, request);
            out.values.resize(n);
            for (std::size_t k = 0; k < n; ++k) {
                const float v = std::isnan(result.svf[k]) ? 1.0f : result.svf[k];
                out.values[k] = raster::srgb_eotf(std::clamp((v - kSvfBlack) / (1.0f - kSvfBlack), 0.0f, 1.0f));
            }
            break;
        }
        case TileStyle::color: {
            // Land cover from the true heights and slopes (a snow line does not move with the
            // exaggeration); the light on the exaggerated form.
            const render::NormalField true_normals = render::terrain_normals(true_grid, s.threads);
            const auto radiance = render_frame(grid, render::rule_materials(true_grid, true_normals), s, progress);
            const float scale = float(kColorExposure / flat_reference(grid, s));
            out.channels = 3;
            out.values.resize(3 * n);
            for (std::size_t k = 0; k < n; ++k)
                for (int c = 0; c < 3; ++c) out.values[3 * k + std::size_t(c)] = radiance[k][c] * scale;
            break;
        }
        default: break;
    }
    return out;
}

}  // namespace ts::tiles
