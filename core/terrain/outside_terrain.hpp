#pragma once
// Texels outside the terrain: those with no height (NaN) once the DEM's holes are filled. That is
// nodata connected to the DEM's border (a reprojection's collar), holes wider than the fill's
// max distance, and every void of a DEM read with --no-fill (core/dem/fill_voids.hpp,
// docs/terrain.md). Pictures and tiles show them transparent; they are never shaded, never
// block the sky and never count in an automatic exposure.
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace ts::terrain {

// One byte per texel, 1 outside; empty when every texel has a height (the common case, which
// then costs the pictures nothing and leaves their bytes as they were).
inline std::vector<std::uint8_t> outside_mask(std::span<const float> z) {
    std::vector<std::uint8_t> mask;
    for (std::size_t i = 0; i < z.size(); ++i)
        if (std::isnan(z[i])) {
            if (mask.empty()) mask.assign(z.size(), 0);
            mask[i] = 1;
        }
    return mask;
}

// What a map leaves transparent: the texels outside the terrain and every void the reader
// filled (`void_mask` 1): their heights are invented to shade their neighbours, not shown, as
// hillshade and tiles leave them. Empty when neither exists.
inline std::vector<std::uint8_t> unmeasured_mask(std::span<const float> z, std::span<const std::uint8_t> void_mask) {
    std::vector<std::uint8_t> mask = outside_mask(z);
    for (std::size_t i = 0; i < void_mask.size() && i < z.size(); ++i)
        if (void_mask[i]) {
            if (mask.empty()) mask.assign(z.size(), 0);
            mask[i] = 1;
        }
    return mask;
}

}  // namespace ts::terrain
