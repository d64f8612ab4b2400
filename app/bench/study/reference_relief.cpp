#include "app/bench/study/reference_relief.hpp"

#include <algorithm>
#include <cmath>

#include "core/render/tone_map.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/tiles/dem_level.hpp"
#include "core/tiles/shade_source.hpp"
#include "core/util/error.hpp"

namespace ts::tiles {
namespace {

render::MaterialRaster grey(std::size_t n) {
    render::MaterialRaster m;
    m.albedo_r.assign(n, 1.0f), m.albedo_g.assign(n, 1.0f), m.albedo_b.assign(n, 1.0f);
    m.ks.assign(n, 0.0f), m.alpha.assign(n, 1.0f);
    m.water.assign(n, 0);
    m.surface.assign(n, render::Surface::bare);
    return m;
}

// Reference luminance of the listed texels of `grid` (albedo 1, Lambert, seen from above).
std::vector<float> reference_luminance(const terrain::HeightGrid& grid, const std::vector<std::size_t>& texels,
                                       const TileShading& s, const render::ReferenceOptions& options) {
    const render::NormalField normals = render::terrain_normals(grid, options.threads);
    const render::MaterialRaster materials = grey(std::size_t(grid.width) * std::size_t(grid.height));
    const render::ViewDirections view;
    const render::ReferenceShader shader(grid, materials, normals, view, texels, options);
    const render::SunState sun{s.sun_azimuth_deg, s.sun_elevation_deg};
    const auto sky = light::make_sky(s.sky, render::sun_direction(sun));
    const std::vector<render::ReferenceSample> samples = shader.render(*sky, sun);
    std::vector<float> out(samples.size());
    for (std::size_t k = 0; k < samples.size(); ++k) out[k] = render::luminance(samples[k].radiance);
    return out;
}

}  // namespace

std::vector<float> reference_relief(const dem::Dem& dem, const TileShading& s, int level, double vertical_scale,
                                    const LevelWindow& w, const render::ReferenceOptions& options) {
    const dem::Dem lvl = dem_level(dem, level, s.threads);
    if (w.col0 < 0 || w.row0 < 0 || w.width <= 0 || w.height <= 0 || w.col0 + w.width > lvl.width ||
        w.row0 + w.height > lvl.height)
        throw InputError("reference window: outside the " + std::to_string(lvl.width) + "x" +
                         std::to_string(lvl.height) + " level");
    std::vector<float> scaled(lvl.z.size());
    for (std::size_t k = 0; k < scaled.size(); ++k) scaled[k] = float(lvl.z[k] * vertical_scale);
    terrain::HeightGrid grid = terrain::metric_view(lvl);
    grid.z = scaled;
    std::vector<std::size_t> texels;
    for (int r = 0; r < w.height; ++r)
        for (int c = 0; c < w.width; ++c) texels.push_back(grid.index(w.col0 + c, w.row0 + r));
    const std::vector<float> lum = reference_luminance(grid, texels, s, options);

    // The same light on open flat ground at the window's spacing.
    constexpr int n = 33;
    const std::vector<float> flat_z(std::size_t(n) * n, 0.0f);
    const std::size_t mid = std::size_t(w.row0 + w.height / 2);
    const terrain::HeightGrid flat = terrain::HeightGrid::uniform(n, n, flat_z, grid.dx_m[mid], grid.dy_m[mid]);
    const double flat_lum = reference_luminance(flat, {std::size_t(n / 2) * n + n / 2}, s, options)[0];

    std::vector<float> out(lum.size());
    for (std::size_t k = 0; k < lum.size(); ++k)
        out[k] = std::isnan(lum[k]) ? lum[k] : relief_grey(lum[k] / flat_lum, s.relief_contrast);
    return out;
}

}  // namespace ts::tiles
