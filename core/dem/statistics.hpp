#pragma once
// Height statistics over the measured cells (voids excluded), as gdalinfo -stats computes them.
#include <cstddef>

#include "core/dem/dem.hpp"

namespace ts::dem {

struct HeightStats {
    double min = 0, max = 0, mean = 0;  // NaN when every cell is a void
    std::size_t valid_count = 0;
    std::size_t void_count = 0;
};

HeightStats height_stats(const Dem& dem);

}  // namespace ts::dem
