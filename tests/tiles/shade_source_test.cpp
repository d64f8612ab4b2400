// core/tiles/shade_source: a level shaded in blocks (bounded memory) gives the whole level's
// values. svf and the sky of relief are the same horizons (every block's receivers swept over the
// whole level), so svf is identical. relief and color take their sun shadows from each block's
// window, where the sun sweep's lines fall at other offsets than on the whole level: a few texels
// on shadow edges differ (here ~0.2% of them, by at most 0.004 display-linear, under one sRGB
// code); a shadow reaching past a halo would differ more, which a halo longer than every shadow
// here rules out.
#include "core/tiles/shade_source.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace ts::tiles {
namespace {

// 150 x 130 texels of 1/1200 degree at 45 N: ridges and a cone, heights 0..~1500 m.
dem::Dem hills() {
    dem::Dem d;
    d.width = 150, d.height = 130;
    d.z.resize(std::size_t(d.width) * std::size_t(d.height));
    d.void_mask.assign(d.z.size(), 0);
    for (int r = 0; r < d.height; ++r)
        for (int c = 0; c < d.width; ++c) {
            const double ridge = 400.0 * (1 + std::sin(c * 0.11 + 0.3 * std::sin(r * 0.05))) * (1 + std::cos(r * 0.07));
            const double cone = std::max(0.0, 700.0 - 25.0 * std::hypot(c - 100.0, r - 40.0));
            d.z[d.index(c, r)] = float(ridge + cone);
        }
    geo::GeoTransform t;
    t.x0 = 6.0, t.dx_col = 1.0 / 1200, t.y0 = 45.0, t.dy_row = -1.0 / 1200;
    d.georef = geo::Georef(d.width, d.height, t, geo::Crs::wgs84(), true);
    return d;
}

void expect_blocked_equals_whole(TileStyle style, float tolerance, double share) {
    const dem::Dem dem = hills();
    TileShading s;
    s.style = style;
    s.directions = 8;
    s.threads = 2;
    s.block_texels = 0;
    const ShadeSource whole = make_shade_source(dem, s, 0, 1.0);
    s.block_texels = 64;  // 3 x 3 blocks, the last ones partial
    s.block_halo_texels = 48;
    const ShadeSource blocked = make_shade_source(dem, s, 0, 1.0);
    ASSERT_EQ(whole.values.size(), blocked.values.size());
    ASSERT_EQ(whole.values.size(), std::size_t(dem.width) * std::size_t(dem.height) * std::size_t(whole.channels));
    double worst = 0;
    std::size_t differ = 0;
    for (std::size_t k = 0; k < whole.values.size(); ++k) {
        const double e = std::abs(whole.values[k] - blocked.values[k]);
        worst = std::max(worst, e);
        differ += e > 1e-6;
    }
    EXPECT_LE(worst, tolerance);
    EXPECT_LE(double(differ), share * double(whole.values.size())) << differ << " values differ";
}

TEST(ShadeSource, SvfInBlocksEqualsTheWholeLevel) { expect_blocked_equals_whole(TileStyle::svf, 0.0f, 0.0); }

TEST(ShadeSource, ReliefInBlocksEqualsTheWholeLevel) { expect_blocked_equals_whole(TileStyle::relief, 0.005f, 0.005); }

TEST(ShadeSource, ColorInBlocksEqualsTheWholeLevel) { expect_blocked_equals_whole(TileStyle::color, 0.005f, 0.005); }

}  // namespace
}  // namespace ts::tiles
