#include "core/dem/dem.hpp"

#include <algorithm>

namespace ts::dem {

std::size_t Dem::void_count() const {
    return std::size_t(std::count_if(void_mask.begin(), void_mask.end(), [](std::uint8_t v) { return v != 0; }));
}

}  // namespace ts::dem
