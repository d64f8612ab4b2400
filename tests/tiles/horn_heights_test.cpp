// The heights a Horn style (hillshade, multidirectional) shades a tile from, where a zoom
// magnifies its DEM level: ETOPO1's 1-degree rows near the North Pole span 5-11 pixels of a
// zoom-2 tile. Bilinear heights give each texel row its own constant north-south slope, so the
// slope jumps at every texel line and Horn drew the rows as bands across the map; cubic heights
// (the default --resampling) change the slope smoothly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/dem/read_dem.hpp"
#include "core/tiles/tile_export.hpp"

namespace ts::tiles {
namespace {

const std::string kPolarEtopo = std::string(TS_SHARED_DATA) + "/dem/etopo1_global_1deg.tif";

// Per row of the tile, the mean over its columns of |z(j+1) - 2 z(j) + z(j-1)|: how much the
// north-south slope changes there. The largest row's over the median row's: a band's row stands
// out, a smooth surface's do not.
double slope_jump_ratio(const std::vector<float>& z, int m) {
    std::vector<double> rows;
    for (int j = 1; j + 1 < m; ++j) {
        double sum = 0;
        for (int i = 0; i < m; ++i) {
            const std::size_t k = std::size_t(j) * std::size_t(m) + std::size_t(i);
            sum += std::abs(double(z[k + std::size_t(m)]) - 2.0 * z[k] + z[k - std::size_t(m)]);
        }
        rows.push_back(sum / m);
    }
    std::vector<double> sorted = rows;
    std::sort(sorted.begin(), sorted.end());
    return sorted.back() / std::max(sorted[sorted.size() / 2], 1e-9);
}

TEST(HornHeights, CubicHeightsOfAMagnifiedLevelHaveNoBandsAlongItsTexelRows) {
    const dem::Dem dem = dem::read_dem(kPolarEtopo);
    TileJob job;
    job.z0 = job.z1 = 2;
    const int m = job.tile_size + 2;
    for (const int x : {0, 1, 2, 3}) {  // the northernmost row of zoom-2 tiles: 66.5 to 85.05 N
        job.shading.resampling = Resampling::bilinear;
        const double bilinear = slope_jump_ratio(tile_heights(dem, job, {2, x, 0}).z, m);
        job.shading.resampling = Resampling::cubic;
        const double cubic = slope_jump_ratio(tile_heights(dem, job, {2, x, 0}).z, m);
        std::printf("tile 2/%d/0: largest row's slope change over the median row's: bilinear %.1f, cubic %.1f\n", x,
                    bilinear, cubic);
        // Measured: bilinear 313-853, cubic 5.5-7.1.
        EXPECT_GT(bilinear, 100.0);
        EXPECT_LT(cubic, 12.0);
    }
}

}  // namespace
}  // namespace ts::tiles
