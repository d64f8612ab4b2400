#pragma once
// Materials per texel, with the BRDFs of brdf.hpp and fresnel.hpp: Lambert albedo (linear
// RGB), an optional Phong lobe (ks, alpha) and water (a Fresnel mirror over a dark diffuse body,
// water_albedo 0.02).
//
// Where they come from (render --materials):
//  - rule (default): from height and slope, blended smoothly so class borders do not show as
//    contour lines; thresholds in MaterialRule (docs/rendering.md has the table);
//  - a land-cover raster: ESA WorldCover class codes (10 tree cover ... 100 moss and lichen);
// and the albedo may be replaced by an orthophoto (material_sources.hpp). Water is always
// decided here: a DEM void, or a flat texel at or below sea level, or WorldCover class 80.
// (Namespace ts::render until the renderer's files say material::, docs/architecture.md.)
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "core/terrain/terrain_normals.hpp"
#include "core/terrain/height_grid.hpp"

namespace ts::render {

inline constexpr float kWaterAlbedo = 0.02f;  // diffuse body of water under the Fresnel mirror
inline constexpr double kWaterIor = 1.333;

// The surface classes the renderer knows, with WorldCover's codes where it has one.
enum class Surface : std::uint8_t {
    water = 80,
    tree_cover = 10,
    shrubland = 20,
    grassland = 30,
    cropland = 40,
    built_up = 50,
    bare = 60,
    snow_ice = 70,
    wetland = 90,
    mangroves = 95,
    moss_lichen = 100,
    rock = 200,  // not a WorldCover class: the rule's steep or high bare rock
};

struct MaterialParams {
    glm::vec3 albedo{0.18f};
    float ks = 0.0f;      // Phong weight (0 = Lambert only)
    float alpha = 1.0f;   // Phong exponent, 1..1000
};

// The look of each class (linear albedo, Phong lobe).
MaterialParams surface_params(Surface s);
// WorldCover code -> class; false for an unknown code (0 = no data).
bool surface_from_worldcover(int code, Surface& out);
std::string_view surface_name(Surface s);

// The elevation/slope rule; every threshold in metres above the DEM datum or degrees.
struct MaterialRule {
    double sea_level_m = 0.0;        // water: height <= this on a flat texel ...
    double water_max_slope_deg = 1.0; // ... flatter than this
    double valley_max_slope_deg = 6.0;  // below: open valley floor (grass/fields), above: forest
    double lowland_m = 700.0;        // flat ground below this: mostly fields and towns (+-150 m blend)
    double treeline_m = 1900.0;      // forest gives way to alpine meadow (+-100 m blend)
    double alpine_rock_m = 2400.0;   // meadow gives way to rock and scree (+-200 m blend)
    double rock_slope_deg = 38.0;    // steeper: bare rock at any height (+-8 deg blend)
    double snow_line_m = 2900.0;     // snow above (+-150 m blend) ...
    double snow_max_slope_deg = 50.0;  // ... except on cliffs too steep to hold it (+-5 deg)
};

// SoA, one entry per texel, row-major like the grid.
struct MaterialRaster {
    std::vector<float> albedo_r, albedo_g, albedo_b;
    std::vector<float> ks, alpha;
    std::vector<std::uint8_t> water;       // 1 = water
    std::vector<Surface> surface;          // the dominant class (for legends and tests)
    std::size_t size() const { return water.size(); }
};

// Water rule: void (source nodata), or flat and at or below sea level.
bool is_water(bool was_void, float height_m, float normal_z, const MaterialRule& rule);

// What texel (c, r) is before any colour: water (no height, the water rule, or WorldCover's
// water) or land, with its WorldCover class when the raster gives one (`known`).
struct TexelCover {
    bool water = false, known = false;
    Surface surface{};
};
TexelCover texel_cover(const terrain::HeightGrid& grid, const NormalField& normals,
                       const std::vector<std::uint8_t>& worldcover, const MaterialRule& rule, int c, int r);

MaterialRaster rule_materials(const terrain::HeightGrid& grid, const NormalField& normals,
                              const MaterialRule& rule = {});

// From WorldCover codes per texel (already on the DEM grid; 0 = no data -> the rule decides).
MaterialRaster landcover_materials(const terrain::HeightGrid& grid, const NormalField& normals,
                                   const std::vector<std::uint8_t>& worldcover, const MaterialRule& rule = {});

// Replaces the albedo of every non-water texel by the given linear RGB (NaN entries keep the
// material's albedo), as an orthophoto gives it.
void apply_albedo(MaterialRaster& m, const std::vector<glm::vec3>& linear_albedo);

// Cartographic albedo (render --albedo-contrast): "light and shadow first, colour second". Real
// land albedos span 2-3x in luminance (forest ~0.05, fields ~0.12), so under a soft light (an
// overcast sky, low relief) the picture reads as a land-cover map and the relief is lost. Each
// land texel's luminance L is pulled towards a fixed reference L0 = 0.10 in log space and its
// tint t = RGB / L towards the tint of vegetated land t0 by the same share,
//   L' = L0^(1 - c) L^c,   t' = t0 + c (t - t0),   RGB' = L' t',
// so c = 1 keeps the physical albedos and c = 0 makes every land texel the same colour. Bright
// surfaces (snow, L above 0.3 to 0.5) and water are kept as they are. A fixed reference, not the
// scene's mean, so that tiles and crops of one DEM get the same albedo.
inline constexpr double kAlbedoReferenceLuminance = 0.10;
glm::vec3 compressed_albedo(const glm::vec3& linear_albedo, double contrast);
void compress_albedo_contrast(MaterialRaster& m, double contrast);

}  // namespace ts::render
