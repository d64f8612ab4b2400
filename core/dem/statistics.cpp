#include "core/dem/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ts::dem {

HeightStats height_stats(const Dem& dem) {
    HeightStats s;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    double sum = 0;  // double: a 3601^2 int16 tile sums exactly (< 2^53)
    for (std::size_t i = 0; i < dem.z.size(); ++i) {
        if (dem.void_mask[i] || std::isnan(dem.z[i])) {
            ++s.void_count;
            continue;
        }
        const double v = dem.z[i];
        lo = std::min(lo, v);
        hi = std::max(hi, v);
        sum += v;
        ++s.valid_count;
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    s.min = s.valid_count ? lo : nan;
    s.max = s.valid_count ? hi : nan;
    s.mean = s.valid_count ? sum / double(s.valid_count) : nan;
    return s;
}

}  // namespace ts::dem
