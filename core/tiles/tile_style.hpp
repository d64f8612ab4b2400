#pragma once
// What a tile shows and how it is lit (docs/tiles.md, "Styles").
#include <optional>
#include <string>
#include <string_view>

#include "core/light/sky.hpp"

namespace ts::tiles {

enum class TileStyle {
    relief,            // grey shaded relief: sun with cast shadows + sky through log-SH visibility
    hillshade,         // Horn, as gdaldem hillshade on the tile's pixels
    multidirectional,  // as gdaldem hillshade -multidirectional
    svf,               // sky view factor, grey
    color,             // the renderer's rule materials under sun and sky
};

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
TileStyle parse_tile_style(std::string_view text);
std::string_view tile_style_name(TileStyle s);
// True for the styles computed from visibility over the whole DEM (relief, svf, color).
inline bool uses_visibility(TileStyle s) { return s == TileStyle::relief || s == TileStyle::svf || s == TileStyle::color; }

struct TileShading {
    TileStyle style = TileStyle::relief;
    // The light, user-facing degrees (azimuth clockwise from north). Cartographic default: from
    // the north-west, 45 deg up. --time sets them from the sun's position instead.
    double sun_azimuth_deg = 315.0;
    double sun_elevation_deg = 45.0;
    double z_factor = 1.0;
    // Replaces the zoom-dependent exaggeration (zoom_exaggeration.hpp) when set.
    std::optional<double> exaggeration;
    light::SkyOptions sky;     // relief, color
    int directions = 16;       // horizon azimuths of the visibility (relief, svf, color)
    // --max-error (relief, color; > 0): a level shaded in blocks takes each block's directions
    // from the block's own roughness (quality::choose_radiance), so flat blocks get fewer; a
    // level in one block keeps `directions` (the zoom's choice). 0: every block `directions`.
    double max_error = 0;
    // Levels wider or taller than this many texels are shaded in blocks of it (relief, svf,
    // color), so memory follows the block, not the DEM (shade_source.hpp). 0 = never.
    int block_texels = 2048;
    // relief, svf, color: each block is shaded on its window grown by this many texels per side
    // (the sun's cast shadows reach that far; the sky sees the exact horizons that far and the
    // far field beyond).
    int block_halo_texels = 256;
    // relief, svf, color in blocks: the sky's terrain beyond the halo.
    FarFieldMethod far_field = FarFieldMethod::balanced;
    Resampling resampling = Resampling::cubic;  // relief, svf, color
    // relief: the shading's contrast in stops about open flat ground (relief_grey,
    // shade_source.hpp); 1 = the physical picture, 1.5 for print.
    double relief_contrast = 1.0;
    int threads = 0;
};

}  // namespace ts::tiles
