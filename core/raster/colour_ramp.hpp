#pragma once
// Colour ramps for pictures of a quantity (quick-looks, their legends, insolation tiles): a
// value scaled to [0, 1] (clamped) to 8-bit sRGB.
#include <cstdint>

namespace ts::raster {

using Ramp = void (*)(float x, std::uint8_t* rgb);
// matplotlib's "inferno" (a public, perceptually uniform colour map) through five stops: for
// energies, dark (little) to bright (much).
void inferno_ramp(float x, std::uint8_t* rgb);
// Grey 1..255, as quick-looks of a fraction are stretched.
void grey_ramp(float x, std::uint8_t* rgb);

}  // namespace ts::raster
