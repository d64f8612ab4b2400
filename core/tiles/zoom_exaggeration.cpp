#include "core/tiles/zoom_exaggeration.hpp"

#include <algorithm>
#include <cmath>

namespace ts::tiles {

double zoom_exaggeration(int pixel_zoom) {
    return std::exp2(std::max(0, kExaggerationFreeZoom - pixel_zoom) / 3.0);
}

int pyramid_level_for(double dem_texel_m, double pixel_ground_m, int max_level) {
    if (!(dem_texel_m > 0) || !(pixel_ground_m > dem_texel_m)) return 0;
    const int level = int(std::floor(std::log2(pixel_ground_m / dem_texel_m)));
    return std::clamp(level, 0, std::max(0, max_level));
}

}  // namespace ts::tiles
