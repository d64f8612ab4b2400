#pragma once
// A texel of a w x h row-major grid, the index clamped to the edge (the pyramid's border rule).
#include <algorithm>
#include <cstddef>
#include <vector>

namespace ts::terrain::test {

inline float clamped(const std::vector<float>& v, int w, int h, int c, int r) {
    c = std::clamp(c, 0, w - 1);
    r = std::clamp(r, 0, h - 1);
    return v[std::size_t(r) * std::size_t(w) + std::size_t(c)];
}

}  // namespace ts::terrain::test
