#pragma once
// Small synthetic terrains with known horizons, for the visibility tests.
#include <cmath>
#include <functional>
#include <vector>

#include "core/terrain/height_grid.hpp"

namespace ts::visibility::testing {

// Owns the heights a HeightGrid views.
struct Terrain {
    std::vector<float> z;
    terrain::HeightGrid grid;
};

// z(x, y) in metres with x east, y north of the centre texel, on a uniform dx x dy grid.
inline Terrain make_terrain(int w, int h, double dx, double dy, const std::function<double(double, double)>& f) {
    Terrain t;
    t.z.resize(std::size_t(w) * h);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) t.z[std::size_t(r) * w + c] = float(f((c - w / 2) * dx, (h / 2 - r) * dy));
    t.grid = terrain::HeightGrid::uniform(w, h, t.z, dx, dy);
    return t;
}

// Rolling hills: a few sines, smooth but with real horizons in every direction.
inline double hills(double x, double y) {
    return 300.0 * std::sin(x / 900.0) * std::cos(y / 1300.0) + 120.0 * std::sin((x + 2 * y) / 400.0) +
           40.0 * std::cos((3 * x - y) / 170.0);
}

}  // namespace ts::visibility::testing
