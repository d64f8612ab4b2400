#include "core/material/palette_materials.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/dem/statistics.hpp"
#include "core/util/angles.hpp"
#include "core/util/smoothstep.hpp"

namespace ts::render {
namespace {

// Half the height over which land hands over to snow at the snow line.
constexpr double kSnowBlendM = 75.0;

}  // namespace

ColorDesign fit_colors(const ColorDesign& design, double lowest_m, double highest_m) {
    ColorDesign d = design;
    d.fitted = true;
    d.sea_floor = lowest_m < kSeaFloorBelowM;
    // Only the built-in hypsometric tints split at sea level: a user's N% keeps gdaldem's meaning
    // (of the whole range).
    if (d.sea_floor && design.palette.name() == kDefaultPalette && design.palette.has_percent_stops())
        d.palette = design.palette.fitted(0.0, std::max(highest_m, 1.0)).with_sea_tints(lowest_m);
    else
        d.palette = design.palette.fitted(lowest_m, highest_m);
    return d;
}

ColorDesign fit_colors(const ColorDesign& design, const dem::Dem& dem) {
    if (design.fitted) return design;
    const dem::HeightStats stats = dem::height_stats(dem);
    if (stats.valid_count == 0) return fit_colors(design, 0.0, 0.0);
    return fit_colors(design, stats.min, stats.max);
}

MaterialRaster palette_materials(const terrain::HeightGrid& g, const NormalField& n, const ColorDesign& design,
                                 const std::vector<std::uint8_t>& worldcover, const MaterialRule& given_rule) {
    const std::size_t count = std::size_t(g.width) * std::size_t(g.height);
    MaterialRaster m;
    m.albedo_r.resize(count), m.albedo_g.resize(count), m.albedo_b.resize(count);
    m.ks.assign(count, 0.0f), m.alpha.assign(count, 1.0f);
    m.water.assign(count, 0);
    m.surface.assign(count, Surface::bare);
    // A DEM with a sea floor has no sea surface to find (ColorDesign::sea_floor).
    MaterialRule rule = given_rule;
    if (design.sea_floor) rule.sea_level_m = -std::numeric_limits<double>::infinity();
    const MaterialParams water = surface_params(Surface::water);
    const MaterialParams snow = surface_params(Surface::snow_ice);
    for (int r = 0; r < g.height; ++r)
        for (int c = 0; c < g.width; ++c) {
            const std::size_t i = g.index(c, r);
            const float h = g.z[i];
            const TexelCover cover = texel_cover(g, n, worldcover, rule, c, r);
            if (cover.water) {
                m.albedo_r[i] = m.albedo_g[i] = m.albedo_b[i] = water.albedo.x;
                m.water[i] = 1;
                m.surface[i] = Surface::water;
                continue;
            }
            MaterialParams land;
            if (cover.known) {
                land = surface_params(cover.surface);
                m.surface[i] = cover.surface;
            } else {
                land.albedo = design.palette.albedo_at(h);
            }
            if (design.snow_line_m) {
                const double t = smoothstep(*design.snow_line_m - kSnowBlendM, *design.snow_line_m + kSnowBlendM, h) *
                                 (1.0 - smoothstep(rule.snow_max_slope_deg - 5, rule.snow_max_slope_deg + 5,
                                                   slope_deg(n.z[i])));
                const float u = float(t);
                land.albedo += (snow.albedo - land.albedo) * u;
                land.ks += (snow.ks - land.ks) * u;
                land.alpha = float(std::exp(std::log(land.alpha) + (std::log(snow.alpha) - std::log(land.alpha)) * t));
                if (t > 0.5) m.surface[i] = Surface::snow_ice;
            }
            m.albedo_r[i] = land.albedo.x, m.albedo_g[i] = land.albedo.y, m.albedo_b[i] = land.albedo.z;
            m.ks[i] = land.ks, m.alpha[i] = land.alpha;
        }
    return m;
}

}  // namespace ts::render
