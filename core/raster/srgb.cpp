#include "core/raster/srgb.hpp"

#include "core/raster/display_shared.hpp"

#include <algorithm>
#include <cmath>

namespace ts::raster {

float srgb_oetf(float c) { return shared::ts_srgb_oetf(c); }

float srgb_eotf(float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

}  // namespace ts::raster
