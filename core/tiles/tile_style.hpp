#pragma once
// What a tile shows and how it is lit (docs/tiles.md, "Styles").
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/light/sky.hpp"
#include "core/render/bounce_transfer.hpp"
#include "core/render/horizon_sky_light.hpp"
#include "core/material/palette_materials.hpp"

namespace ts::tiles {

// `color`'s exposure: an open flat texel of albedo 1 lands here before the filmic curve, so a
// meadow (albedo ~0.15-0.2) lands near the filmic's middle grey. Lightable tiles' readers get it
// in lightable.json.
inline constexpr double kColorExposure = 2.2;

struct TileFrame;
struct TileShading;
struct HornLight;
struct BlockShading;
struct TileInsolation;

// One tile style: its name, what its zoom's source holds, how a tile's pixels are made and
// which options it takes. One class per style, each in its own file (relief_style.cpp,
// hillshade_style.cpp, multidirectional_style.cpp, svf_style.cpp, color_style.cpp,
// insolation_style.cpp), listed in
// tile_styles() (tile_style.cpp). A new style is one file and one line there
// (docs/architecture.md).
class TileStyle {
public:
    virtual ~TileStyle() = default;
    // The name users give (`--style`), lower case.
    virtual std::string_view name() const = 0;
    // Styles with visibility shade their values once over each zoom's DEM level
    // (shade_source.hpp, shade_block); the others shade each tile from its heights (shade_tile).
    virtual bool uses_visibility() const = 0;
    // Values per source texel: 1 (grey) or 3 (RGB); a data style (lightable) more, by its shading.
    virtual int channels() const { return 1; }
    virtual int channels(const TileShading&) const { return channels(); }
    // A data tile: the tile's sampled values are encoded by the style (encode_data_tile), not as
    // a picture.
    virtual bool data_tile() const { return false; }
    // RGB values are scene-linear light for the filmic curve (color); false: display-linear
    // colours, sRGB-encoded as they are (a colour ramp's).
    virtual bool filmic() const { return false; }
    // The level's true (not exaggerated) heights are kept for shade_block (land cover).
    virtual bool needs_true_heights() const { return false; }
    // Values relative to open flat ground under the same light (BlockShading::flat).
    virtual bool relative_to_flat() const { return false; }
    // Without a far field a block is shaded on its core grown by the halo; false: on its core,
    // its horizons swept over the whole level.
    virtual bool halo_without_far_field() const { return true; }
    // The radiance error bound chooses its directions (per zoom, per block).
    virtual bool takes_max_error() const { return false; }
    // Takes a contrast about open flat ground (TileShading::relief_contrast).
    virtual bool takes_relief_contrast() const { return false; }
    // Colours land with TileShading::colors (a palette, a snow line); the others are grey.
    virtual bool colours_land() const { return false; }
    // Reads each texel's latitude (BlockShading::latitude): the sun's path depends on it.
    virtual bool needs_latitudes() const { return false; }

    // Styles without visibility: a tile's grey values 1..255 from its heights ((size + 2)^2
    // with the 1-px halo), written where `covered`.
    virtual void shade_tile(const TileFrame& f, const std::vector<float>& heights, double vertical_scale,
                            const HornLight& light, const std::uint8_t* covered, std::uint8_t* out) const;
    // Styles with visibility: `channels` display-linear values per texel of the block's window.
    virtual std::vector<float> shade_block(const BlockShading& block) const;
};

// Every style, in the order users read them (registry in tile_style.cpp).
const std::vector<const TileStyle*>& tile_styles();
// The style of that name, or null.
const TileStyle* find_tile_style(std::string_view name);
// The default style (relief).
const TileStyle& default_tile_style();
// "relief | hillshade | ..." for help texts.
std::string tile_style_names(std::string_view separator);

// How a block of a level shaded in blocks sees the terrain beyond its halo (shade_source.hpp).
enum class FarFieldMethod {
    exact,     // the exact sweep over the whole level for every block: exact, ~N / block sweeps
    fast,      // mean levels marched at 2, 4, 8 or 16 samples per octave of distance
    balanced,  // (core/visibility/far_field_horizons.hpp)
    fine,
    finest,
};

// "exact", "balanced", ...; throws ts::InputError naming --far-field otherwise.
FarFieldMethod parse_far_field(std::string_view text);
std::string_view far_field_name(FarFieldMethod m);
// The march's samples per octave (0 for exact).
int far_field_samples_per_octave(FarFieldMethod m);

// How relief, svf and color tiles sample their source between texels (hillshade and
// multidirectional take bilinear heights, as gdaldem's pipeline).
enum class Resampling {
    bilinear,
    cubic,  // Catmull-Rom: crisp where a zoom magnifies its level
};

// "bilinear" or "cubic"; throws ts::InputError naming --resampling otherwise.
Resampling parse_resampling(std::string_view text);
std::string_view resampling_name(Resampling r);

// "relief", "hillshade", ...; throws ts::InputError naming --style otherwise.
const TileStyle& parse_tile_style(std::string_view text);

struct TileShading {
    const TileStyle* style = &default_tile_style();
    // The light, user-facing degrees (azimuth clockwise from north). Cartographic default: from
    // the north-west, 45 deg up. --time sets them from the sun's position instead.
    double sun_azimuth_deg = 315.0;
    double sun_elevation_deg = 45.0;
    // Where true north lies on the DEM's grid (Georef::grid_azimuth_of_north_deg at its centre):
    // the styles shaded on the DEM's levels (relief, color) turn the sun by it. Tiles' own pixels
    // (hillshade) are Web Mercator, whose north is true north.
    double grid_north_deg = 0.0;
    double z_factor = 1.0;
    // Replaces the zoom-dependent exaggeration (zoom_exaggeration.hpp) when set.
    std::optional<double> exaggeration;
    light::SkyOptions sky;     // relief, color
    render::ColorDesign colors;  // color: the land colours, fitted to the whole DEM's heights
    int directions = 16;       // horizon azimuths of the visibility (relief, svf, color, insolation: 64)
    render::BounceSettings bounce;  // light bounced off the terrain (relief, color, lightable)
    // The sky's light over the horizons or through SH (relief, color; lightable tiles are lit by
    // the browser through SH: sh there).
    render::SkyLightSettings sky_light;
    // --max-error (relief, color; > 0): a level shaded in blocks takes each block's directions
    // from the block's own roughness (quality::choose_radiance), so flat blocks get fewer; a
    // level in one block keeps `directions` (the zoom's choice). 0: every block `directions`.
    double max_error = 0;
    // Levels wider or taller than this many texels are shaded in blocks of it (relief, svf,
    // color), so memory follows the block, not the DEM (shade_source.hpp). 0 = never.
    int block_texels = 2048;
    // relief, svf, color, insolation: each block is shaded on its window grown by this many texels per side
    // (the sun's cast shadows reach that far; the sky sees the exact horizons that far and the
    // far field beyond).
    int block_halo_texels = 256;
    // relief, svf, color, insolation in blocks: the sky's terrain beyond the halo.
    FarFieldMethod far_field = FarFieldMethod::balanced;
    Resampling resampling = Resampling::cubic;  // relief, svf, color
    // relief: the shading's contrast in stops about open flat ground (relief_grey,
    // shade_source.hpp); 1 = the physical picture, 1.5 for print.
    double relief_contrast = 1.0;
    // lightable: horizon azimuths stored per pixel (the sun's visibility at any instant) and the
    // principal components a tile keeps of the diffuse transfer (lightable_tile.hpp).
    int light_directions = 128;
    int light_components = 6;
    // insolation: the range's sun and the ramp (tile_insolation.hpp), set once the DEM is read.
    std::shared_ptr<const TileInsolation> insolation;
    int threads = 0;
};

}  // namespace ts::tiles
