#pragma once
// What the tiles of one pixel zoom are cut from: a raster on a DEM pyramid level, computed once
// over the whole level (so horizons and cast shadows see terrain far beyond any tile) and then
// sampled per tile pixel (tile_renderer.hpp).
//
//   hillshade, multidirectional   the level's heights (the tile takes its gradients itself, in
//                                 map pixels: equal to gdaldem on the tile's pixels)
//   relief                        grey: sun (cast shadows) + sky (log-SH visibility) on a grey
//                                 Lambert ground, relative to an open flat texel under the same
//                                 light; display-linear 0..1
//   svf                           sky view factor, stretched to display-linear 0..1
//   color                         the land colours of --colors (and --snow-line), linear RGB exposed for the filmic
//                                 curve (render --view map's look, with a fixed exposure)
// Heights are multiplied by z-factor x exaggeration before any of this (zoom_exaggeration.hpp).
//
// Memory: a level wider or taller than TileShading::block_texels is shaded block by block, so
// the ~200 bytes per texel of a shading state are held for one block's window at a time, not
// the level (the level itself costs ~12 bytes per texel: heights, shaded heights, values). A
// block is shaded on its window, the block grown by block_halo_texels on each side: its
// normals, sun shadows and the sky's exact horizons come from the window, and the terrain
// beyond it from the far field (core/visibility/far_field_horizons.hpp: the level's mean levels
// from the one matching the halo's distance on, marched for the sky's horizons and the sun's
// azimuth), built once per level. With --far-field exact, a block's sky instead sweeps its
// receivers over every texel of the level (the whole-level horizons, at one sweep of the level
// per block) and its sun shadows end at the halo.
#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "core/dem/dem.hpp"
#include "core/tiles/tile_style.hpp"

namespace ts {
class ProgressBar;
}

namespace ts::tiles {

struct ShadeSource {
    int level = 0;               // 2^level DEM texels per source texel side
    int width = 0, height = 0;   // texels
    int channels = 1;            // 1, or 3 (color, insolation)
    bool filmic = false;         // RGB through the filmic curve (TileStyle::filmic)
    double vertical_scale = 1;   // z-factor x exaggeration the values were computed with
    std::vector<float> values;   // row-major, `channels` floats per texel
    std::map<int, int> blocks_by_directions;  // horizon directions -> blocks shaded with them
};

// Display-linear grey of an open flat texel in `relief` (0.5 -> sRGB code 188): slopes facing
// the sun go brighter, shade and shadow darker, with room on both sides.
inline constexpr float kReliefFlatGrey = 0.5f;

// The display-linear grey of a texel whose luminance is `ratio` times that of open flat ground
// under the same light, with the shading's contrast in stops multiplied by `contrast`
// (grey = flat grey x ratio^contrast): a slope one stop brighter than the flat becomes `contrast`
// stops brighter, a shadow as many stops darker. A function of the texel alone, so tiles stay
// seamless (unlike a stretch from a picture's statistics).
inline float relief_grey(double ratio, double contrast) {
    const double r = contrast == 1.0 ? ratio : std::pow(std::max(ratio, 0.0), contrast);
    return std::clamp(float(kReliefFlatGrey * r), 0.0f, 1.0f);
}

// The source of `style` on DEM level `level` with heights times `vertical_scale`. The visibility
// styles advance `progress` (may be null) per texel and horizon azimuth.
ShadeSource make_shade_source(const dem::Dem& dem, const TileShading& shading, int level, double vertical_scale,
                              ProgressBar* progress = nullptr);

}  // namespace ts::tiles
