#include "core/raster/colour_ramp.hpp"

#include <algorithm>
#include <cmath>

namespace ts::raster {
namespace {

// The stops of "inferno" sampled at 0, .25, .5, .75, 1.
constexpr float kInferno[5][3] = {{0, 0, 4}, {87, 16, 110}, {188, 55, 84}, {249, 142, 9}, {252, 255, 164}};

}  // namespace

void inferno_ramp(float x, std::uint8_t* rgb) {
    x = std::clamp(x, 0.0f, 1.0f) * 4.0f;
    const int i = std::min(3, int(x));
    const float f = x - float(i);
    for (int c = 0; c < 3; ++c)
        rgb[c] = std::uint8_t(std::lround(kInferno[i][c] + f * (kInferno[i + 1][c] - kInferno[i][c])));
}

void grey_ramp(float x, std::uint8_t* rgb) {
    rgb[0] = rgb[1] = rgb[2] = std::uint8_t(1.5f + std::clamp(x, 0.0f, 1.0f) * 254.0f);
}

}  // namespace ts::raster
