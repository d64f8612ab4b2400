#pragma once
// Crack pixels of a flythrough frame: sky (depth 0: reversed Z, cleared to 0) with terrain above
// and below it in the same column. A height field seen by an upright camera covers each column of
// the middle of the picture (nearly vertical planes) in one run, so any such gap is a crack
// between LOD patches or tiles.
#include <cstddef>
#include <vector>

namespace ts::gpu::test_support {

// Over the columns [x0 w, x1 w) of a w x h depth buffer.
inline int crack_pixels(const std::vector<float>& depth, int w, int h, double x0 = 0.3, double x1 = 0.7) {
    int cracks = 0;
    for (int x = int(x0 * w); x < int(x1 * w); ++x) {
        int top = -1, bottom = -1;
        for (int y = 0; y < h; ++y)
            if (depth[std::size_t(y) * std::size_t(w) + std::size_t(x)] > 0.0f) {
                if (top < 0) top = y;
                bottom = y;
            }
        for (int y = top + 1; top >= 0 && y < bottom; ++y)
            if (depth[std::size_t(y) * std::size_t(w) + std::size_t(x)] == 0.0f) ++cracks;
    }
    return cracks;
}

}  // namespace ts::gpu::test_support
