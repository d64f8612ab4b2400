#include "core/terrain/terrain_normals.hpp"

#include <algorithm>
#include <cmath>

#include "core/util/angles.hpp"
#include "core/util/parallel_for.hpp"

namespace ts::render {
namespace {

// d(height)/d(index) along one axis at index i of n samples read through get(i); NaN-aware.
template <class Get>
double derivative(int i, int n, Get&& get) {
    const float here = get(i);
    const float prev = i > 0 ? get(i - 1) : NAN;
    const float next = i + 1 < n ? get(i + 1) : NAN;
    const bool p = !std::isnan(prev), q = !std::isnan(next);
    if (p && q) return 0.5 * (double(next) - double(prev));
    if (q && !std::isnan(here)) return double(next) - double(here);
    if (p && !std::isnan(here)) return double(here) - double(prev);
    return 0.0;
}

}  // namespace

NormalField terrain_normals(const terrain::HeightGrid& g, int threads) {
    NormalField n;
    const std::size_t count = std::size_t(g.width) * std::size_t(g.height);
    n.x.assign(count, 0.0f);
    n.y.assign(count, 0.0f);
    n.z.assign(count, 1.0f);
    parallel_rows(g.height, threads, g.width * 20LL, [&](int r0, int r1) {
        for (int r = r0; r < r1; ++r)
            for (int c = 0; c < g.width; ++c) {
                const std::size_t i = g.index(c, r);
                if (std::isnan(g.z[i])) continue;
                const double dzdc = derivative(c, g.width, [&](int k) { return g.at(k, r); });
                const double dzdr = derivative(r, g.height, [&](int k) { return g.at(c, k); });
                // A row at a pole is one point (dx_m 0): no east-west slope, not 0/0.
                const double dx = g.dx_m[std::size_t(r)];
                const double dzdx = dx > 0 ? dzdc / dx : 0.0;
                // Rows run north to south: +row is -y.
                const double dzdy = -dzdr / g.dy_m[std::size_t(r)];
                const double len = std::sqrt(dzdx * dzdx + dzdy * dzdy + 1.0);
                n.x[i] = float(-dzdx / len);
                n.y[i] = float(-dzdy / len);
                n.z[i] = float(1.0 / len);
            }
    });
    return n;
}

double slope_deg(float nz) {
    return degrees(std::acos(std::clamp(double(nz), -1.0, 1.0)));
}

}  // namespace ts::render
