#pragma once
// The broadband (0.3-3 um) shortwave albedo of each ESA WorldCover class, for the reflected
// irradiation of the insolation maps. Not the renderer's RGB albedos (core/material): those are
// the visible band, where vegetation is dark; in the shortwave its near-infrared reflectance
// doubles it. Values are mid-points of the ranges in T. R. Oke, Boundary Layer Climates, 2nd ed.
// (1987), table 1.1 (docs/insolation.md, "Albedo"); permanent snow and ice mixes old snow, firn
// and glacier ice.
#include <cstdint>
#include <span>
#include <vector>

namespace ts::solar {

// The class's albedo, or `fallback` for 0 (no data) and codes WorldCover does not define.
float worldcover_shortwave_albedo(std::uint8_t code, float fallback);

// Per texel from WorldCover codes on the DEM's grid.
std::vector<float> shortwave_albedo_of(std::span<const std::uint8_t> codes, float fallback);

}  // namespace ts::solar
