#include "core/tiles/block_shading.hpp"

#include <algorithm>
#include <memory>

#include "core/render/frame_renderer.hpp"
#include "core/render/shading_state.hpp"
#include "core/render/tone_map.hpp"
#include "core/render/view_shading.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/visibility/window_visibility_backend.hpp"

namespace ts::tiles {
namespace {

// Shades a block's window from the sun by the level's terrain beyond it (empty: none).
using OuterSunShadow = std::function<void(const render::SunState&, std::vector<float>&)>;

render::RendererOptions renderer_options(const TileShading& s, ProgressBar* progress,
                                         visibility::VisibilityBackend* backend, OuterSunShadow outer_sun) {
    render::RendererOptions o;
    o.outer_sun_shadow = std::move(outer_sun);
    o.directions = s.directions;
    o.bounce = s.bounce;
    o.sky_light = s.sky_light;
    // The bounce's gather looks no farther than a block's halo (less the bilinear cell and a
    // texel), so that a block's core gathers the same terrain as the whole level does.
    o.bounce.gather.radius_texels =
        std::min(o.bounce.gather.radius_texels, std::max(1.0, double(s.block_halo_texels - 2)));
    o.threads = s.threads;
    o.progress = progress;
    o.visibility = backend;
    return o;
}

// One frame of radiance on `grid` with `materials`; `backend` null = the CPU on `grid`. With
// `inspect`, the state (its transfer kept) goes there instead and no frame is rendered.
std::vector<glm::vec3> render_frame(const terrain::HeightGrid& grid, render::MaterialRaster materials,
                                    const TileShading& s, ProgressBar* progress,
                                    visibility::VisibilityBackend* backend = nullptr, OuterSunShadow outer_sun = {},
                                    const StateInspector* inspect = nullptr) {
    render::NormalField normals = render::terrain_normals(grid, s.threads);
    render::RendererOptions options = renderer_options(s, progress, backend, std::move(outer_sun));
    options.keep_diffuse_transfer = inspect != nullptr;
    auto state = render::compute_shading_state(grid, std::move(materials), std::move(normals), options);
    if (inspect) {
        (*inspect)(*state);
        return {};
    }
    const render::ViewShading view = render::compute_view_shading(*state, {});
    render::FrameRenderer frame(*state, view);
    const render::SunState sun = render::sun_on_grid({s.sun_azimuth_deg, s.sun_elevation_deg}, s.grid_north_deg);
    const auto sky = light::make_sky(render::sky_for(s.sky, s.sky_light), render::sun_direction(sun));
    std::vector<glm::vec3> radiance;
    frame.render(*sky, sun, radiance);
    return radiance;
}

}  // namespace

render::MaterialRaster grey_materials(std::size_t n, float albedo) {
    render::MaterialRaster m;
    m.albedo_r.assign(n, albedo), m.albedo_g.assign(n, albedo), m.albedo_b.assign(n, albedo);
    m.ks.assign(n, 0.0f), m.alpha.assign(n, 1.0f);
    m.water.assign(n, 0);
    m.surface.assign(n, render::Surface::bare);
    return m;
}

namespace {

// The centre texel of open flat ground (32 x 32 texels of dx x dy) rendered under the shading's
// light, or its state handed to `inspect`.
constexpr int kFlatTexels = 32;
constexpr std::size_t kFlatCentre = std::size_t(kFlatTexels / 2) * kFlatTexels + kFlatTexels / 2;

std::vector<glm::vec3> render_flat(double dx, double dy, const TileShading& s, const StateInspector* inspect = nullptr) {
    const std::vector<float> z(std::size_t(kFlatTexels) * kFlatTexels, 0.0f);
    const terrain::HeightGrid flat = terrain::HeightGrid::uniform(kFlatTexels, kFlatTexels, z, dx, dy);
    TileShading quiet = s;
    quiet.threads = 1;
    return render_frame(flat, grey_materials(z.size(), 1.0f), quiet, nullptr, nullptr, {}, inspect);
}

}  // namespace

double flat_reference(const terrain::HeightGrid& like, const TileShading& s) {
    const std::size_t mid_row = std::size_t(like.height / 2);
    return render::luminance(render_flat(like.dx_m[mid_row], like.dy_m[mid_row], s)[kFlatCentre]);
}

std::array<float, 16> flat_diffuse_transfer(const TileShading& s) {
    std::array<float, 16> t{};
    const StateInspector keep = [&](const render::ShadingState& state) {
        const std::vector<float>& td = state.kept_diffuse_transfer();
        for (int i = 0; i < 16; ++i) t[std::size_t(i)] = td[std::size_t(i) * state.texels() + kFlatCentre];
    };
    // The transfer of open flat ground does not depend on the spacing.
    render_flat(30.0, 30.0, s, &keep);
    return t;
}

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


std::vector<glm::vec3> render_block(const BlockShading& b, const BlockMaterials& materials, bool true_heights,
                                    const StateInspector* inspect) {
    std::vector<float> wz, wtrue;
    std::vector<std::uint8_t> wvoids, wtrue_voids;
    std::unique_ptr<visibility::WindowFarFieldVisibility> backend;
    terrain::HeightGrid g = b.grid, tg = b.true_grid;
    OuterSunShadow outer_sun;
    if (!b.whole) {
        g = window_grid(b.grid, b.window, wz, wvoids);
        if (true_heights) tg = window_grid(b.true_grid, b.window, wtrue, wtrue_voids);
        backend = b.far ? std::make_unique<visibility::WindowFarFieldVisibility>(b.window, b.core, *b.far)
                        : std::make_unique<visibility::WindowFarFieldVisibility>(b.window, b.core, b.grid);
    }
    // The far field shades the core from the sun past the halo (the sweep's shadows end there).
    if (b.far) outer_sun = visibility::far_field_sun_shadow(b.window, b.core, *b.far, g);
    return render_frame(g, materials(g, tg), b.shading, b.progress, backend.get(), outer_sun, inspect);
}

visibility::VisibilityResult block_visibility(const BlockShading& b, visibility::VisibilityRequest request,
                                              const terrain::HeightGrid& window_texels) {
    const Rect& w = b.window;
    request.horizon.window = {w.col0, w.row0, w.width, w.height};
    if (b.far) return visibility::WindowFarFieldVisibility(w, b.core, *b.far).compute(window_texels, request);
    return visibility::make_cpu_visibility_backend()->compute(b.grid, request);
}

std::vector<float> block_svf(const BlockShading& b) {
    visibility::VisibilityRequest request;
    request.horizon.directions = b.shading.directions;
    request.horizon.threads = b.shading.threads;
    request.horizon.progress = b.progress;
    request.svf = true;
    std::vector<float> sz;
    std::vector<std::uint8_t> svoids;
    // The window's own grid only for the far field (without one the level is swept as it is).
    const terrain::HeightGrid g = b.far ? window_grid(b.grid, b.window, sz, svoids) : terrain::HeightGrid{};
    const visibility::VisibilityResult result = block_visibility(b, request, g);
    return std::vector<float>(result.svf.begin(), result.svf.end());
}

}  // namespace ts::tiles
