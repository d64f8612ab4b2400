#pragma once
// The centred width x height window of a height grid as a grid of its own: its heights copied,
// its rows' spacing kept (benches and tests measure crops of large DEMs). `grid` views `z`, so
// a GridCrop may be moved (the vector keeps its buffer) but not copied.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/terrain/height_grid.hpp"

namespace ts::terrain {

struct GridCrop {
    std::vector<float> z;
    HeightGrid grid;

    GridCrop() = default;
    GridCrop(GridCrop&&) = default;
    GridCrop& operator=(GridCrop&&) = default;
    GridCrop(const GridCrop&) = delete;
    GridCrop& operator=(const GridCrop&) = delete;
};

// At most width x height texels from the centre of g (all of g where it is smaller).
// The source's void mask is not carried over (its voids stay NaN heights).
inline GridCrop centre_crop(const HeightGrid& g, int width, int height) {
    const int w = std::min(width, g.width), h = std::min(height, g.height);
    const int c0 = (g.width - w) / 2, r0 = (g.height - h) / 2;
    GridCrop out;
    out.z.resize(std::size_t(w) * std::size_t(h));
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) out.z[std::size_t(r) * std::size_t(w) + std::size_t(c)] = g.at(c0 + c, r0 + r);
    out.grid.width = w;
    out.grid.height = h;
    out.grid.z = out.z;
    out.grid.dx_m.assign(g.dx_m.begin() + r0, g.dx_m.begin() + r0 + h);
    out.grid.dy_m.assign(g.dy_m.begin() + r0, g.dy_m.begin() + r0 + h);
    return out;
}

}  // namespace ts::terrain
