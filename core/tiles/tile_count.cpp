#include "core/tiles/tile_count.hpp"

#include <algorithm>
#include <cmath>

namespace ts::tiles {

std::int64_t count_tiles_covering(const LonLatBox& box, int z) {
    if (box.empty()) return 0;
    const glm::dvec2 sw = lonlat_to_mercator({box.west, box.south});
    const glm::dvec2 ne = lonlat_to_mercator({box.east, box.north});
    const double size = 2.0 * kOriginShiftM / double(tiles_per_side(z));
    const std::int64_t last = tiles_per_side(z) - 1;
    // The same half-open rule as tiles_covering: an edge on a tile border takes no extra tile.
    auto first_index = [&](double v) { return std::clamp<std::int64_t>(std::int64_t(std::floor(v / size)), 0, last); };
    auto last_index = [&](double v) { return std::clamp<std::int64_t>(std::int64_t(std::ceil(v / size)) - 1, 0, last); };
    const std::int64_t x0 = first_index(sw.x + kOriginShiftM), x1 = last_index(ne.x + kOriginShiftM);
    const std::int64_t y0 = first_index(kOriginShiftM - ne.y), y1 = last_index(kOriginShiftM - sw.y);
    return std::max<std::int64_t>(0, x1 - x0 + 1) * std::max<std::int64_t>(0, y1 - y0 + 1);
}

}  // namespace ts::tiles
