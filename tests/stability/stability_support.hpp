#pragma once
// Shared pieces of the stability suite: synthetic terrains where the methods are pushed to
// their limits, the raymarch reference, and error measures that also count NaN and values
// outside their physical range (a NaN must fail a test, never vanish from an RMSE).
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

#include "core/terrain/height_grid.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/horizon_set.hpp"
#include "core/visibility/sky_integrals.hpp"

namespace ts::stability {

// Owns the heights a HeightGrid views; x east, y north of the centre texel, in metres.
struct Terrain {
    std::vector<float> z;
    terrain::HeightGrid grid;
};

inline Terrain make_terrain(int w, int h, double cell_m, const std::function<double(int col, int row)>& f) {
    Terrain t;
    t.z.resize(std::size_t(w) * h);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) t.z[std::size_t(r) * w + c] = float(f(c, r));
    t.grid = terrain::HeightGrid::uniform(w, h, t.z, cell_m, cell_m);
    return t;
}

inline visibility::HorizonOptions horizon_options(visibility::HorizonMethod m, int directions, bool curvature = true) {
    visibility::HorizonOptions o;
    o.method = m;
    o.directions = directions;
    o.curvature = curvature;
    o.threads = 2;
    return o;
}

// svf compared texel by texel: RMSE and largest difference over texels both give (interior
// only when `skip_edge`), and how many texels of `got` are NaN where `want` is not, or
// outside [0, 1].
struct SvfComparison {
    double rmse = 0, max_abs = 0;
    long compared = 0, nan = 0, out_of_range = 0;
};

inline SvfComparison compare_svf(const std::vector<float>& got, const std::vector<float>& want, int w, int h,
                                 bool skip_edge = true) {
    SvfComparison s;
    double se = 0;
    const int e = skip_edge ? 1 : 0;
    for (int r = e; r < h - e; ++r)
        for (int c = e; c < w - e; ++c) {
            const std::size_t i = std::size_t(r) * w + c;
            if (std::isnan(want[i])) continue;
            if (std::isnan(got[i])) {
                ++s.nan;
                continue;
            }
            if (got[i] < 0.0f || got[i] > 1.0f) ++s.out_of_range;
            const double d = std::abs(double(got[i]) - want[i]);
            se += d * d;
            s.max_abs = std::max(s.max_abs, d);
            ++s.compared;
        }
    s.rmse = s.compared ? std::sqrt(se / double(s.compared)) : 0.0;
    return s;
}

// The reference: raymarched horizons (1/4-texel steps to the grid's edge) at 128 azimuths (4x the default D).
inline std::vector<float> reference_svf(const terrain::HeightGrid& g, bool curvature = true) {
    const auto set = visibility::compute_horizons(g, horizon_options(visibility::HorizonMethod::raymarch, 128, curvature));
    return visibility::svf_raster(set);
}

inline std::vector<float> method_svf(const terrain::HeightGrid& g, visibility::HorizonMethod m, int directions = 32,
                                     bool curvature = true) {
    return visibility::svf_raster(visibility::compute_horizons(g, horizon_options(m, directions, curvature)));
}

}  // namespace ts::stability
