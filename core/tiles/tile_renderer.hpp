#pragma once
// One tile's pixels from its pixel zoom's ShadeSource: locate every pixel on the DEM
// (tile_pixels.hpp), sample the source bilinearly at the pixel's position on the source's level,
// and shade (Horn styles) or encode (the others). Grey styles give grey + alpha, color RGBA;
// alpha is 0 off the DEM and over its voids, 255 elsewhere. A pure function of (tile, source,
// shading): neighbouring tiles and the 2x2 / 512-px tilings of the same pixels agree exactly.
#include <cstdint>
#include <vector>

#include "core/tiles/lightable_tile.hpp"
#include "core/tiles/shade_source.hpp"
#include "core/tiles/tile_pixels.hpp"
#include "core/tiles/tile_style.hpp"

namespace ts::tiles {

struct TileImage {
    int size = 0;
    int channels = 0;                 // 2 (grey, alpha) or 4 (RGBA)
    std::vector<std::uint8_t> pixels;
    std::size_t covered = 0;          // pixels with alpha 255
    std::vector<std::uint8_t> encoded;  // a data tile's bytes (lightable); pixels then unused
};

// Per-thread buffers, kept from tile to tile.
struct TileScratch {
    std::vector<glm::dvec2> at;
    std::vector<float> values;
    std::vector<std::uint8_t> covered, grey;
};

// The heights a Horn style shades the tile from: (size + 2)^2 floats with the 1-px halo, into
// scratch.values (scratch.at holds the pixels' DEM positions). render_tile calls it. Cubic
// (Catmull-Rom, where all 16 taps have a height; bilinear beside voids) keeps the surface's
// slope continuous across texel lines: where a zoom magnifies its level (a 1-degree grid near
// the poles, any DEM past its native zoom) bilinear heights give each texel row its own constant
// slope, and Horn drew them as bands.
void sample_tile_heights(const TilePixelMap& map, const ShadeSource& source, const TileFrame& f, TileScratch& scratch,
                         Resampling resampling = Resampling::cubic);

// A data style's tile (TileStyle::data_tile) comes out in `out.encoded`, `lightable` its encoding.
void render_tile(const TilePixelMap& map, const ShadeSource& source, const TileShading& shading, const TileFrame& f,
                 TileScratch& scratch, TileImage& out, const LightableEncoding* lightable = nullptr);

}  // namespace ts::tiles
