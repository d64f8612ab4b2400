#include "core/terrain/isotropic_rows.hpp"

#include <algorithm>
#include <cmath>

namespace ts::terrain {

int isotropic_half_width(const HeightGrid& g, int row) {
    const double dx = g.dx_m[std::size_t(row)], dy = g.dy_m[std::size_t(row)];
    if (!(dx > 0) || !(dy >= 2.0 * dx)) return 0;
    return std::min(int(std::floor(dy / dx / 2.0)), std::max(0, g.width / 2));
}

void make_rows_isotropic(const HeightGrid& g, std::vector<float>& z) {
    std::vector<double> sum(std::size_t(g.width) + 1);
    std::vector<int> count(std::size_t(g.width) + 1);
    for (int r = 0; r < g.height; ++r) {
        const int k = isotropic_half_width(g, r);
        if (k == 0) continue;
        float* row = z.data() + std::size_t(r) * std::size_t(g.width);
        // Prefix sums of the finite heights and their count: each box in O(1).
        for (int c = 0; c < g.width; ++c) {
            const bool finite = std::isfinite(row[c]);
            sum[std::size_t(c) + 1] = sum[std::size_t(c)] + (finite ? double(row[c]) : 0.0);
            count[std::size_t(c) + 1] = count[std::size_t(c)] + (finite ? 1 : 0);
        }
        for (int c = 0; c < g.width; ++c) {
            if (!std::isfinite(row[c])) continue;
            const int a = std::max(0, c - k), b = std::min(g.width, c + k + 1);
            row[c] = float((sum[std::size_t(b)] - sum[std::size_t(a)]) / double(count[std::size_t(b)] - count[std::size_t(a)]));
        }
    }
}

}  // namespace ts::terrain
