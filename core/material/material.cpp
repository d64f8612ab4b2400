#include "core/material/material.hpp"

#include <algorithm>
#include <cmath>

#include "core/util/angles.hpp"
#include "core/util/smoothstep.hpp"

namespace ts::render {
namespace {

struct Blend {
    glm::vec3 albedo{0.0f};
    float ks = 0, log_alpha = 0;
};

Blend blend_of(Surface s) {
    const MaterialParams p = surface_params(s);
    return {p.albedo, p.ks, std::log(p.alpha)};
}

Blend mix(const Blend& a, const Blend& b, double t) {
    const float u = float(t);
    return {a.albedo + (b.albedo - a.albedo) * u, a.ks + (b.ks - a.ks) * u, a.log_alpha + (b.log_alpha - a.log_alpha) * u};
}

MaterialRaster allocate(std::size_t n) {
    MaterialRaster m;
    m.albedo_r.resize(n), m.albedo_g.resize(n), m.albedo_b.resize(n);
    m.ks.resize(n), m.alpha.resize(n, 1.0f);
    m.water.assign(n, 0);
    m.surface.assign(n, Surface::grassland);
    return m;
}

void store(MaterialRaster& m, std::size_t i, const Blend& b, Surface s) {
    m.albedo_r[i] = b.albedo.x, m.albedo_g[i] = b.albedo.y, m.albedo_b[i] = b.albedo.z;
    m.ks[i] = b.ks;
    m.alpha[i] = std::exp(b.log_alpha);
    m.surface[i] = s;
}

void store_water(MaterialRaster& m, std::size_t i) {
    store(m, i, blend_of(Surface::water), Surface::water);
    m.water[i] = 1;
}

// The rule for one land texel: a base of valley grass, forest on slopes below the treeline,
// meadow above it, then rock (steep or high) and snow (high, not on cliffs) laid over.
void rule_texel(MaterialRaster& m, std::size_t i, double h, double slope, const MaterialRule& r) {
    const double t_forest = smoothstep(r.valley_max_slope_deg - 3, r.valley_max_slope_deg + 3, slope) *
                            (1.0 - smoothstep(r.treeline_m - 100, r.treeline_m + 100, h));
    const double t_rock = std::max(smoothstep(r.rock_slope_deg - 8, r.rock_slope_deg + 8, slope),
                                   smoothstep(r.alpine_rock_m - 200, r.alpine_rock_m + 200, h));
    const double t_snow = smoothstep(r.snow_line_m - 150, r.snow_line_m + 150, h) *
                          (1.0 - smoothstep(r.snow_max_slope_deg - 5, r.snow_max_slope_deg + 5, slope));
    // Flat low ground is mostly fields and towns, paler than meadow.
    const double t_fields = (1.0 - smoothstep(r.valley_max_slope_deg - 4, r.valley_max_slope_deg, slope)) *
                            (1.0 - smoothstep(r.lowland_m - 150, r.lowland_m + 150, h));
    Blend b = mix(blend_of(Surface::grassland), blend_of(Surface::cropland), 0.7 * t_fields);
    b = mix(b, blend_of(Surface::tree_cover), t_forest);
    b = mix(b, blend_of(Surface::rock), t_rock);
    b = mix(b, blend_of(Surface::snow_ice), t_snow);
    Surface s = t_forest > 0.5 ? Surface::tree_cover : Surface::grassland;
    if (t_rock > 0.5) s = Surface::rock;
    if (t_snow > 0.5) s = Surface::snow_ice;
    store(m, i, b, s);
}

}  // namespace

MaterialParams surface_params(Surface s) {
    // Linear albedos from typical broadband/visible reflectances (e.g. the ASTER/ECOSTRESS
    // spectral library and MODIS albedo climatologies), tinted per channel: forest ~0.05,
    // grass ~0.1, dry rock ~0.2, fresh snow ~0.8. Phong only where a sheen is expected.
    switch (s) {
        case Surface::water: return {glm::vec3(kWaterAlbedo), 0.0f, 1.0f};
        case Surface::tree_cover: return {{0.035f, 0.060f, 0.028f}, 0.0f, 1.0f};
        case Surface::shrubland: return {{0.070f, 0.095f, 0.045f}, 0.0f, 1.0f};
        case Surface::grassland: return {{0.080f, 0.105f, 0.050f}, 0.0f, 1.0f};
        case Surface::cropland: return {{0.130f, 0.125f, 0.075f}, 0.0f, 1.0f};
        case Surface::built_up: return {{0.190f, 0.180f, 0.170f}, 0.02f, 20.0f};
        case Surface::bare: return {{0.260f, 0.235f, 0.200f}, 0.0f, 1.0f};
        case Surface::snow_ice: return {{0.800f, 0.830f, 0.880f}, 0.06f, 30.0f};
        case Surface::wetland: return {{0.060f, 0.090f, 0.050f}, 0.0f, 1.0f};
        case Surface::mangroves: return {{0.040f, 0.070f, 0.030f}, 0.0f, 1.0f};
        case Surface::moss_lichen: return {{0.120f, 0.140f, 0.090f}, 0.0f, 1.0f};
        case Surface::rock: return {{0.165f, 0.150f, 0.130f}, 0.03f, 8.0f};
    }
    return {};
}

bool surface_from_worldcover(int code, Surface& out) {
    switch (code) {
        case 10: case 20: case 30: case 40: case 50: case 60: case 70: case 80: case 90: case 95: case 100:
            out = Surface(code);
            return true;
        default: return false;
    }
}

std::string_view surface_name(Surface s) {
    switch (s) {
        case Surface::water: return "water";
        case Surface::tree_cover: return "tree cover";
        case Surface::shrubland: return "shrubland";
        case Surface::grassland: return "grassland";
        case Surface::cropland: return "cropland";
        case Surface::built_up: return "built-up";
        case Surface::bare: return "bare / sparse vegetation";
        case Surface::snow_ice: return "snow and ice";
        case Surface::wetland: return "herbaceous wetland";
        case Surface::mangroves: return "mangroves";
        case Surface::moss_lichen: return "moss and lichen";
        case Surface::rock: return "rock";
    }
    return "?";
}

bool is_water(bool was_void, float h, float nz, const MaterialRule& rule) {
    if (was_void) return true;
    const double cos_max = std::cos(radians(rule.water_max_slope_deg));
    return double(h) <= rule.sea_level_m && double(nz) >= cos_max;
}

TexelCover texel_cover(const terrain::HeightGrid& g, const NormalField& n, const std::vector<std::uint8_t>& worldcover,
                       const MaterialRule& rule, int c, int r) {
    const std::size_t i = g.index(c, r);
    const float h = g.z[i];
    TexelCover t;
    t.known = i < worldcover.size() && surface_from_worldcover(worldcover[i], t.surface);
    t.water = std::isnan(h) || is_water(g.was_void(c, r), h, n.z[i], rule) || (t.known && t.surface == Surface::water);
    return t;
}

MaterialRaster rule_materials(const terrain::HeightGrid& g, const NormalField& n, const MaterialRule& rule) {
    const std::size_t count = std::size_t(g.width) * std::size_t(g.height);
    MaterialRaster m = allocate(count);
    for (int r = 0; r < g.height; ++r)
        for (int c = 0; c < g.width; ++c) {
            const std::size_t i = g.index(c, r);
            const float h = g.z[i];
            if (std::isnan(h) || is_water(g.was_void(c, r), h, n.z[i], rule)) {
                store_water(m, i);
                continue;
            }
            rule_texel(m, i, h, slope_deg(n.z[i]), rule);
        }
    return m;
}

MaterialRaster landcover_materials(const terrain::HeightGrid& g, const NormalField& n,
                                   const std::vector<std::uint8_t>& worldcover, const MaterialRule& rule) {
    const std::size_t count = std::size_t(g.width) * std::size_t(g.height);
    MaterialRaster m = allocate(count);
    for (int r = 0; r < g.height; ++r)
        for (int c = 0; c < g.width; ++c) {
            const std::size_t i = g.index(c, r);
            const TexelCover t = texel_cover(g, n, worldcover, rule, c, r);
            if (t.water) {
                store_water(m, i);
            } else if (t.known) {
                store(m, i, blend_of(t.surface), t.surface);
            } else {
                rule_texel(m, i, g.z[i], slope_deg(n.z[i]), rule);
            }
        }
    return m;
}

namespace {
// The tint of mid-latitude vegetated land (RGB over Rec. 709 luminance, between the grass and
// forest albedos of surface_params): the colour every land texel moves towards.
constexpr glm::dvec3 kLandTintRaw{0.80, 1.11, 0.53};
constexpr glm::dvec3 kLandTint = kLandTintRaw / (0.2126 * kLandTintRaw.x + 0.7152 * kLandTintRaw.y + 0.0722 * kLandTintRaw.z);
}  // namespace

glm::vec3 compressed_albedo(const glm::vec3& albedo, double contrast) {
    if (contrast >= 1.0) return albedo;
    const double c = std::max(0.0, contrast);
    const double r = albedo.x, g = albedo.y, b = albedo.z;
    const double lum = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    if (!(lum > 0.0)) return albedo;
    // Snow and other bright surfaces keep theirs; a smooth hand-over, no edge at a threshold.
    const double keep = smoothstep(0.3, 0.5, lum);
    const double exponent = c + (1.0 - c) * keep;  // 1 = unchanged
    const double log_ref = std::log(kAlbedoReferenceLuminance);
    const double lum2 = std::exp(log_ref + exponent * (std::log(lum) - log_ref));
    // The tint (RGB / luminance) pulled towards the land reference by the same share.
    const glm::dvec3 tint = glm::dvec3(r, g, b) / lum;
    const glm::dvec3 t2 = kLandTint + exponent * (tint - kLandTint);
    return glm::vec3(lum2 * t2);
}

void compress_albedo_contrast(MaterialRaster& m, double contrast) {
    if (contrast >= 1.0) return;
    for (std::size_t i = 0; i < m.size(); ++i) {
        if (m.water[i]) continue;
        const glm::vec3 a = compressed_albedo({m.albedo_r[i], m.albedo_g[i], m.albedo_b[i]}, contrast);
        m.albedo_r[i] = a.x, m.albedo_g[i] = a.y, m.albedo_b[i] = a.z;
    }
}

void apply_albedo(MaterialRaster& m, const std::vector<glm::vec3>& a) {
    const std::size_t n = std::min(a.size(), m.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (m.water[i] || std::isnan(a[i].x) || std::isnan(a[i].y) || std::isnan(a[i].z)) continue;
        m.albedo_r[i] = a[i].x, m.albedo_g[i] = a[i].y, m.albedo_b[i] = a[i].z;
    }
}

}  // namespace ts::render
