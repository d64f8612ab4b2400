#pragma once
// What a caller that never holds a grid whole gives visibility::FarField, computed here from a
// grid in memory for the tests: a mean level of the grid with its row spacing (as the far field's
// coarse copy takes it), the grid's highest height, and a window of the grid as a grid of its own.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "core/terrain/height_grid.hpp"
#include "core/terrain/height_pyramid.hpp"
#include "core/visibility/horizon_set.hpp"

namespace ts::visibility::testing {

// Owns the heights its grid views: movable (the vector keeps its buffer), not copyable.
struct OwnedGrid {
    std::vector<float> z;
    terrain::HeightGrid grid;

    OwnedGrid() = default;
    OwnedGrid(OwnedGrid&&) = default;
    OwnedGrid& operator=(OwnedGrid&&) = default;
    OwnedGrid(const OwnedGrid&) = delete;
    OwnedGrid& operator=(const OwnedGrid&) = delete;
};

// The grid's mean level `shift`: terrain::downsample_2x2 `shift` times; a level row's spacing is
// the sum of its two finer rows' (the last row of an odd level counted twice).
inline OwnedGrid mean_level(const terrain::HeightGrid& g, int shift) {
    OwnedGrid out;
    out.z.assign(g.z.begin(), g.z.end());
    int w = g.width, h = g.height;
    std::vector<double> dx = g.dx_m, dy = g.dy_m;
    for (int k = 0; k < shift; ++k) {
        out.z = terrain::downsample_2x2(out.z.data(), w, h, false, 2);
        const int half = (h + 1) / 2;
        const auto n = std::size_t(half);
        std::vector<double> cdx(n), cdy(n);
        for (int r = 0; r < half; ++r) {
            const auto r0 = std::size_t(2 * r), r1 = std::size_t(std::min(2 * r + 1, h - 1));
            cdx[std::size_t(r)] = dx[r0] + dx[r1], cdy[std::size_t(r)] = dy[r0] + dy[r1];
        }
        w = (w + 1) / 2, h = half;
        dx = std::move(cdx), dy = std::move(cdy);
    }
    out.grid.width = w, out.grid.height = h;
    out.grid.z = out.z;
    out.grid.dx_m = std::move(dx), out.grid.dy_m = std::move(dy);
    return out;
}

// The highest height, voids (NaN) skipped.
inline float top_height(const terrain::HeightGrid& g) {
    float top = -std::numeric_limits<float>::infinity();
    for (float z : g.z)
        if (!std::isnan(z)) top = std::max(top, z);
    return top;
}

// A rectangle of a grid as a grid of its own (heights copied, its rows' spacing kept).
inline OwnedGrid cut(const terrain::HeightGrid& g, const ReceiverWindow& w) {
    OwnedGrid out;
    out.z.resize(std::size_t(w.width) * std::size_t(w.height));
    for (int r = 0; r < w.height; ++r)
        for (int c = 0; c < w.width; ++c) out.z[std::size_t(r) * std::size_t(w.width) + std::size_t(c)] = g.at(w.col0 + c, w.row0 + r);
    out.grid.width = w.width, out.grid.height = w.height;
    out.grid.z = out.z;
    out.grid.dx_m.assign(g.dx_m.begin() + w.row0, g.dx_m.begin() + w.row0 + w.height);
    out.grid.dy_m.assign(g.dy_m.begin() + w.row0, g.dy_m.begin() + w.row0 + w.height);
    return out;
}

}  // namespace ts::visibility::testing
