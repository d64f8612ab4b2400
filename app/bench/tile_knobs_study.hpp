#pragma once
// `bench tiles --knobs`: the tiles' own speed/accuracy knobs on one DEM, for the report
// (docs/accuracy.md). Relief at the last zoom's level:
//  - block_texels, block_halo and far_field: the level shaded in blocks (the memory bound of a
//    DEM larger than memory) against the same level shaded whole, in sRGB codes;
//  - tile_size: every 512-px tile of zoom z1-1 against the 2x2 256-px tiles of z1 that cover
//    its ground (cut and encoded, the cost of the same ground), in sRGB codes;
//  - level_bias_zZ: zoom Z's tiles from the DEM level its pixels match and from finer and coarser
//    ones, against level 0's relief averaged down to the matched level (shade, cut and encode
//    time; sRGB codes over the covered pixels), for each zoom of the range that has a finer level.
// Rows: knob,value,is_default,seconds,rms_codes,max_codes.
#include <string>

#include "core/dem/dem.hpp"
#include "core/tiles/tile_export.hpp"

namespace ts::app {

void run_tile_knobs_study(const dem::Dem& dem, tiles::TileJob job, const std::string& csv_path);

}  // namespace ts::app
