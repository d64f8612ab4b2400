#pragma once
// How many tiles of zoom z a lon/lat box touches, without listing them: what `plan` reports
// for continental and global jobs, whose lists would not fit in memory. Equals
// tiles_covering(box, z, z).size() (tests/tiles/tile_shard_test.cpp).
#include <cstdint>

#include "core/tiles/dem_footprint.hpp"

namespace ts::tiles {

std::int64_t count_tiles_covering(const LonLatBox& box, int z);

}  // namespace ts::tiles
