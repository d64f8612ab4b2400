// core/tiles/shade_source: a level shaded in blocks (bounded memory) gives the whole level's
// values.
// With --far-field exact, svf and the sky of relief are the same horizons (every block's
// receivers swept over the whole level), so svf is identical. relief and color take their sun
// shadows from each block's window, where the sun sweep's lines fall at other offsets than on
// the whole level: a few texels on shadow edges differ (here ~0.2% of them, by at most 0.004
// display-linear, under one sRGB code).
// With the far field (the default), terrain beyond the halo is marched over coarser levels for
// the sky and the sun: close to the whole level, within the bounds stated below.
#include "core/tiles/shade_source.hpp"

#include <memory>

#include "core/solar/insolation_period.hpp"
#include "core/tiles/tile_insolation.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include <string_view>

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

struct Bounds {
    float max_error;  // display-linear
    double share;     // of the values differing by more than 1e-6
    double rmse;      // display-linear
};

// The sun of two days in June for hills(): 16 azimuths x 4 bins, a 10-minute step.
std::shared_ptr<const TileInsolation> june_sun() {
    solar::InsolationSettings st;
    st.periods = solar::make_periods({2024, 6, 20}, {2024, 6, 21}, solar::PeriodSplit::year, 6.0);
    st.clock_longitude_deg = 6.0;
    st.step_minutes = 10;
    st.azimuth_bins = 32;
    st.svf_stride = 4;
    auto ins = std::make_shared<TileInsolation>();
    ins->model = std::make_shared<const solar::InsolationModel>(st, 44.89, 45.0, 0.05, 0.0, 2300.0, 1000.0);
    ins->lo = 4, ins->hi = 20;  // kWh/m2 over the two days: flat ground ~16
    return ins;
}

void expect_blocked_equals_whole(std::string_view style, FarFieldMethod far, const Bounds& b) {
    const dem::Dem dem = hills();
    TileShading s;
    if (style == "insolation") s.insolation = june_sun();
    s.style = find_tile_style(style);
    s.far_field = far;
    s.directions = 8;
    s.threads = 2;
    // One job's halo for both: the insolation's reflection gathers no farther than it.
    s.block_halo_texels = 48;
    s.block_texels = 0;
    const ShadeSource whole = make_shade_source(dem, s, 0, 1.0);
    s.block_texels = 64;  // 3 x 3 blocks, the last ones partial
    const ShadeSource blocked = make_shade_source(dem, s, 0, 1.0);
    ASSERT_EQ(whole.values.size(), blocked.values.size());
    ASSERT_EQ(whole.values.size(), std::size_t(dem.width) * std::size_t(dem.height) * std::size_t(whole.channels));
    double worst = 0, sum2 = 0;
    std::size_t differ = 0;
    float lo = whole.values[0], hi = whole.values[0];
    for (std::size_t k = 0; k < whole.values.size(); ++k) {
        // hills() has no voids: every value is a number, and they differ (the test could fail).
        ASSERT_TRUE(std::isfinite(whole.values[k]) && std::isfinite(blocked.values[k])) << k;
        lo = std::min(lo, whole.values[k]), hi = std::max(hi, whole.values[k]);
        const double e = std::abs(whole.values[k] - blocked.values[k]);
        worst = std::max(worst, e);
        sum2 += e * e;
        differ += e > 1e-6;
    }
    EXPECT_GT(hi - lo, 0.1f);
    const double rmse = std::sqrt(sum2 / double(whole.values.size()));
    SCOPED_TRACE("max " + std::to_string(worst) + ", rmse " + std::to_string(rmse) + ", " + std::to_string(differ) +
                 " of " + std::to_string(whole.values.size()) + " values differ");
    EXPECT_LE(worst, b.max_error);
    EXPECT_LE(rmse, b.rmse);
    EXPECT_LE(double(differ), b.share * double(whole.values.size()));
}

TEST(ShadeSource, SvfInBlocksEqualsTheWholeLevel) {
    expect_blocked_equals_whole("svf", FarFieldMethod::exact, {0.0f, 0.0, 0.0});
}

// The bounce's sun part reads the sun of the terrain a core texel sees, halo texels too, whose
// shadows from beyond the window a block does not have (the far field shades the core only):
// measured with this 48-texel halo (tiles: 256) 0.55% and 0.51% of the values differ, by at
// most 0.0039 and 0.0042 (a code at most), where the SH sun part kept it under 0.5%.
TEST(ShadeSource, ReliefInBlocksEqualsTheWholeLevel) {
    expect_blocked_equals_whole("relief", FarFieldMethod::exact, {0.005f, 0.008, 0.001});
}

TEST(ShadeSource, ColorInBlocksEqualsTheWholeLevel) {
    expect_blocked_equals_whole("color", FarFieldMethod::exact, {0.005f, 0.008, 0.001});
}

// The insolation of a block takes its horizons like svf (identical with the exact far field)
// and its normals from its window (the halo gives the core's edges their neighbours): equal.
TEST(ShadeSource, InsolationInBlocksEqualsTheWholeLevel) {
    expect_blocked_equals_whole("insolation", FarFieldMethod::exact, {1e-5f, 0.0, 1e-6});
}

TEST(ShadeSource, InsolationInBlocksWithTheFarFieldIsCloseToTheWholeLevel) {
    // Measured: max 0.049, RMS 0.0024 (the far field's marched sky and sun, as svf's).
    expect_blocked_equals_whole("insolation", FarFieldMethod::balanced, {0.06f, 1.0, 0.005});
}

TEST(ShadeSource, SvfInBlocksWithTheFarFieldIsCloseToTheWholeLevel) {
    expect_blocked_equals_whole("svf", FarFieldMethod::balanced, {0.05f, 1.0, 0.005});
}

TEST(ShadeSource, ReliefInBlocksWithTheFarFieldIsCloseToTheWholeLevel) {
    expect_blocked_equals_whole("relief", FarFieldMethod::balanced, {0.05f, 1.0, 0.005});
}

// --relief-contrast k multiplies every texel's distance from open flat ground in stops by k:
// grey_k = flat grey x (grey_1 / flat grey)^k, texel by texel (so tiles stay seamless), and the
// picture's spread of stops grows k-fold where nothing clips.
TEST(ShadeSource, ReliefContrastStretchesEachTexelsStopsAboutTheFlat) {
    EXPECT_FLOAT_EQ(relief_grey(1.0, 1.7), kReliefFlatGrey);
    EXPECT_FLOAT_EQ(relief_grey(0.5, 2.0), kReliefFlatGrey * 0.25f);
    EXPECT_FLOAT_EQ(relief_grey(1.2, 1.0), kReliefFlatGrey * 1.2f);
    EXPECT_EQ(relief_grey(0.0, 1.5), 0.0f);
    EXPECT_EQ(relief_grey(5.0, 1.5), 1.0f);  // clipped
    const dem::Dem dem = hills();
    TileShading s;
    s.style = find_tile_style("relief");
    s.directions = 8;
    s.threads = 2;
    const ShadeSource one = make_shade_source(dem, s, 0, 1.0);
    s.relief_contrast = 1.5;
    const ShadeSource stretched = make_shade_source(dem, s, 0, 1.0);
    ASSERT_EQ(one.values.size(), stretched.values.size());
    double spread_one = 0, spread_stretched = 0;
    std::size_t compared = 0;
    for (std::size_t k = 0; k < one.values.size(); ++k) {
        const float v = one.values[k];
        if (!(v > 0.02f) || v >= 0.99f) continue;
        const float want = relief_grey(v / kReliefFlatGrey, 1.5);
        ASSERT_NEAR(stretched.values[k], want, 1e-5f) << k;
        if (want < 0.99f) {
            spread_one += std::abs(std::log2(v / kReliefFlatGrey));
            spread_stretched += std::abs(std::log2(stretched.values[k] / kReliefFlatGrey));
            ++compared;
        }
    }
    ASSERT_GT(compared, one.values.size() / 2);
    EXPECT_NEAR(spread_stretched / spread_one, 1.5, 1e-3);
}

// A north-south ridge 1500 m high west of flat ground, the sun 15 degrees up in the west: its
// shadow runs ~85 texels east of the crest, past a 32-texel halo. Blocks see it through the far
// field's sun march; with --far-field exact (sun shadows from the window alone) it is cut at
// the halo.
dem::Dem ridge() {
    dem::Dem d;
    d.width = 320, d.height = 64;
    d.z.assign(std::size_t(d.width) * std::size_t(d.height), 100.0f);
    d.void_mask.assign(d.z.size(), 0);
    for (int r = 0; r < d.height; ++r)
        for (int c = 0; c < d.width; ++c) d.z[d.index(c, r)] = float(100.0 + 1500.0 * std::exp(-std::pow((c - 20) / 8.0, 2)));
    geo::GeoTransform t;
    t.x0 = 6.0, t.dx_col = 1.0 / 1200, t.y0 = 45.0, t.dy_row = -1.0 / 1200;
    d.georef = geo::Georef(d.width, d.height, t, geo::Crs::wgs84(), true);
    return d;
}

// Per row, the first column east of the ridge lit again (relief above 0.4), whole and blocked.
struct ShadowEnds {
    std::vector<int> whole, blocked;
};

int shadow_end(const ShadeSource& src, int width, int row) {
    for (int c = 40; c < width; ++c)
        if (src.values[std::size_t(row) * std::size_t(width) + std::size_t(c)] > 0.4f) return c;
    return width;
}

ShadowEnds shadow_ends(FarFieldMethod far) {
    const dem::Dem dem = ridge();
    TileShading s;
    s.style = find_tile_style("relief");
    s.directions = 8;
    s.threads = 2;
    s.sun_azimuth_deg = 270, s.sun_elevation_deg = 15;
    s.far_field = far;
    s.block_texels = 0;
    const ShadeSource whole = make_shade_source(dem, s, 0, 1.0);
    s.block_texels = 64;
    s.block_halo_texels = 32;
    const ShadeSource blocked = make_shade_source(dem, s, 0, 1.0);
    ShadowEnds e;
    for (int r = 0; r < dem.height; ++r) {
        e.whole.push_back(shadow_end(whole, dem.width, r));
        e.blocked.push_back(shadow_end(blocked, dem.width, r));
    }
    return e;
}

// The far field's sun march reads mean levels at 16 samples per octave: near grazing a sample
// falling beside the crest moves the shadow's end by a few texels (here <= 4 of ~85).
TEST(ShadeSource, TheFarFieldCarriesASunShadowPastTheHalo) {
    const ShadowEnds far = shadow_ends(FarFieldMethod::balanced);
    const ShadowEnds cut = shadow_ends(FarFieldMethod::exact);
    for (std::size_t r = 0; r < far.whole.size(); ++r) {
        EXPECT_GE(far.whole[r], 100) << "row " << r << ": the whole level's shadow reaches past the halo";
        EXPECT_NEAR(far.blocked[r], far.whole[r], 4) << "row " << r;
        EXPECT_LE(cut.blocked[r], 64 + 32 + 2) << "row " << r << ": without the far field the shadow ends at the halo";
    }
}

}  // namespace
}  // namespace ts::tiles
