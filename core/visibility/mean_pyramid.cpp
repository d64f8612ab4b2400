#include "core/visibility/mean_pyramid.hpp"

#include <algorithm>
#include <cmath>

#include "core/visibility/surface_sampling.hpp"

namespace ts::visibility {

MeanPyramid::MeanPyramid(const terrain::HeightGrid& grid) {
    levels_.push_back({grid.width, grid.height, std::vector<float>(grid.z.begin(), grid.z.end())});
    while (levels_.back().width > 1 || levels_.back().height > 1) {
        const Level& fine = levels_.back();
        Level coarse{(fine.width + 1) / 2, (fine.height + 1) / 2, {}};
        coarse.z.assign(std::size_t(coarse.width) * coarse.height, kNoHeight);
        for (int r = 0; r < coarse.height; ++r)
            for (int c = 0; c < coarse.width; ++c) {
                float sum = 0;
                int n = 0;
                for (int dr = 0; dr < 2; ++dr)
                    for (int dc = 0; dc < 2; ++dc) {
                        const int fc = std::min(2 * c + dc, fine.width - 1), fr = std::min(2 * r + dr, fine.height - 1);
                        const float v = fine.z[std::size_t(fr) * fine.width + fc];
                        if (!std::isnan(v)) sum += v, ++n;
                    }
                if (n > 0) coarse.z[std::size_t(r) * coarse.width + c] = sum / float(n);
            }
        levels_.push_back(std::move(coarse));
    }
}

float MeanPyramid::sample(int level, double col, double row) const {
    const Level& l = levels_[std::size_t(level)];
    // Level-l texel k covers level-0 texels [k 2^l, (k+1) 2^l): its centre is at (k + 0.5) 2^l - 0.5.
    const double scale = std::ldexp(1.0, -level);
    const double lc = std::clamp((col + 0.5) * scale - 0.5, 0.0, double(l.width - 1));
    const double lr = std::clamp((row + 0.5) * scale - 0.5, 0.0, double(l.height - 1));
    return bilinear_valid(l.z.data(), l.width, l.height, lc, lr);
}

}  // namespace ts::visibility
