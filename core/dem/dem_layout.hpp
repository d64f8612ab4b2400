#pragma once
// The grid of a DEM (one file or a mosaic) without its heights: all a reader learns from
// headers, so a grid can be placed and checked before (or without) decoding its cells.
#include <string>

#include "core/dem/dem.hpp"
#include "core/geo/georef.hpp"

namespace ts::dem {

struct DemLayout {
    int width = 0, height = 0;
    geo::Georef georef;                 // as mosaic(read_dem(...)) would give
    std::string vertical_datum = "unknown";
    // The unit the file stores heights in ("metre", "US survey foot"); readers convert to metres.
    std::string height_unit = "metre";
    std::string credit;                 // Dem::credit
    std::string source;                 // the file(s), for messages
};

// The grid of a Dem.
DemLayout layout_of(const Dem& dem);
// A Dem on `layout` with every cell allocated: z 0, void_mask 0 (readers overwrite them).
Dem allocate_dem(const DemLayout& layout);

}  // namespace ts::dem
