// visibility --max-error (core/quality/visibility_quality.hpp) meets its bound against the
// raymarch reference on the shared DEMs: for each DEM, a 48 x 48 crop away from the centred
// window the table was fitted on, and bounds from loose to tight, the chosen setting's svf
// RMSE (interior texels, 128-azimuth raymarch, as bench visibility measures it) is at most E.
// Also: flat ground gets the cheapest setting, and a bound no setting can meet says so.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "core/dem/read_dem.hpp"
#include "core/quality/visibility_quality.hpp"
#include "core/util/error.hpp"
#include "core/visibility/visibility_grid.hpp"
#include "tests/stability/stability_support.hpp"

namespace ts::stability {
namespace {

dem::Dem crop(const dem::Dem& d, int c0, int r0, int n) {
    dem::Dem out;
    out.width = out.height = n;
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            out.z.push_back(d.at(c0 + c, r0 + r));
            out.void_mask.push_back(d.void_mask.empty() ? 0 : d.void_mask[d.index(c0 + c, r0 + r)]);
        }
    out.georef = d.georef.window(c0, r0, n, n);
    return out;
}

class MaxErrorOnSharedDem : public ::testing::TestWithParam<std::string> {};

TEST_P(MaxErrorOnSharedDem, TheChosenSettingMeetsTheBoundAgainstTheRaymarch) {
    const dem::Dem full = dem::read_dem(std::string(TS_SHARED_DATA) + "/dem/" + GetParam());
    // A quarter of the way in from the north-west corner: not the fitted centre window.
    const dem::Dem d = crop(full, full.width / 4, full.height / 4, 48);
    const visibility::VisibilityGrid grid(d);
    const auto ref = reference_svf(grid.view());
    const double roughness = quality::mean_tan_slope(grid.view());
    int met = 0;
    for (double e : {0.003, 0.001, 0.0005, 0.0003}) {
        const quality::VisibilityChoice choice = quality::choose_visibility(e, roughness);
        auto o = horizon_options(visibility::HorizonMethod::exact, choice.setting.directions);
        o.exact_near_field_texels = choice.setting.near_field_texels;
        const auto svf = visibility::svf_raster(visibility::compute_horizons(grid.view(), o));
        const SvfComparison s = compare_svf(svf, ref, 48, 48);
        if (!choice.met) {
            EXPECT_NE(choice.reason.find("no setting"), std::string::npos) << choice.reason;
            continue;
        }
        ++met;
        std::printf("%s: E %g -> %d directions, near %g: predicted %.2g, measured %.2g\n", GetParam().c_str(), e,
                    choice.setting.directions, choice.setting.near_field_texels, choice.predicted_error, s.rmse);
        EXPECT_LE(s.rmse, e) << GetParam() << ": " << choice.reason << "; measured " << s.rmse;
    }
    EXPECT_GE(met, 2) << "the loose bounds are met by some setting";
}

INSTANTIATE_TEST_SUITE_P(SharedDems, MaxErrorOnSharedDem,
                         ::testing::Values("copernicus_N45E005_grenoble_500px.tif", "srtm3_N39E040_1000px.tif",
                                           "N00E010.hgt", "N00E011.hgt.zip"),
                         [](const ::testing::TestParamInfo<std::string>& p) { return std::to_string(p.index); });

TEST(MaxError, FlatGroundGetsTheCheapestSettingAndAnImpossibleBoundSaysSo) {
    const Terrain flat = make_terrain(32, 32, 30.0, [](int, int) { return 5.0; });
    const double r = quality::mean_tan_slope(flat.grid);
    EXPECT_EQ(r, 0.0);
    const auto cheap = quality::choose_visibility(1e-4, r);
    EXPECT_TRUE(cheap.met);
    EXPECT_EQ(cheap.setting.directions, quality::visibility_settings().front().directions);
    const auto none = quality::choose_visibility(1e-9, 0.5);
    EXPECT_FALSE(none.met);
    EXPECT_EQ(none.setting.directions, quality::visibility_settings().back().directions);
    EXPECT_THROW(quality::choose_visibility(0.0, 0.1), InputError);
}

TEST(MaxError, RoughnessIsTheMeanTangentOfTheSlope) {
    // A plane rising 1 m per 10 m eastwards: tan slope 0.1 everywhere.
    const Terrain plane = make_terrain(20, 20, 10.0, [](int c, int) { return c * 1.0; });
    EXPECT_NEAR(quality::mean_tan_slope(plane.grid), 0.1, 1e-9);
}

}  // namespace
}  // namespace ts::stability
