// --max-error per region (quality::choose_radiance_per_region, the blocks of a tile level):
// flat regions get less work than rough ones, the picture's predicted RMS meets the bound, and
// the choice costs no more than the cheapest single setting that meets it everywhere.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/quality/radiance_quality.hpp"
#include "core/util/error.hpp"

namespace ts {
namespace {

double cost_of(const std::vector<int>& settings, const std::vector<double>& weight) {
    double c = 0;
    for (std::size_t r = 0; r < settings.size(); ++r)
        c += weight[r] * quality::relative_cost(quality::radiance_settings()[std::size_t(settings[r])]);
    return c;
}

double rms(const std::vector<int>& settings, const std::vector<double>& roughness, const std::vector<double>& weight,
           double el) {
    double se = 0, w = 0;
    for (std::size_t r = 0; r < settings.size(); ++r) {
        const double e = quality::predicted_radiance_error(quality::radiance_settings()[std::size_t(settings[r])],
                                                           roughness[r], el);
        se += weight[r] * e * e, w += weight[r];
    }
    return std::sqrt(se / w);
}

TEST(RegionMaxError, FlatRegionsGetLessWorkAndThePictureMeetsTheBound) {
    // Half the picture flat, a quarter gentle, a quarter rough, under a 5-degree sun.
    const std::vector<double> roughness = {0.01, 0.02, 0.12, 0.45}, weight = {1, 1, 1, 1};
    const double el = 5.0;
    for (double e : {0.075, 0.07, 0.068, 0.066}) {
        const quality::RegionChoice c = quality::choose_radiance_per_region(e, roughness, weight, el, false);
        ASSERT_EQ(c.setting.size(), roughness.size());
        if (!c.met) continue;
        EXPECT_LE(c.predicted_error, e + 1e-12) << e;
        EXPECT_NEAR(c.predicted_error, rms(c.setting, roughness, weight, el), 1e-9) << e;
        const auto& s = quality::radiance_settings();
        EXPECT_LE(s[std::size_t(c.setting[0])].directions, s[std::size_t(c.setting[3])].directions) << e;
        // No dearer than the cheapest single setting every region meets the bound with.
        for (int k = 0; k < int(s.size()); ++k) {
            if (s[std::size_t(k)].exact_sun) continue;
            const std::vector<int> uniform(roughness.size(), k);
            if (rms(uniform, roughness, weight, el) <= e) {
                EXPECT_LE(cost_of(c.setting, weight), cost_of(uniform, weight) + 1e-9) << e << " vs D " << s[std::size_t(k)].directions;
                break;
            }
        }
    }
    // The flat regions at the cheapest setting for a bound the rough one needs more for.
    const quality::RegionChoice c = quality::choose_radiance_per_region(0.07, roughness, weight, el, false);
    ASSERT_TRUE(c.met);
    EXPECT_EQ(c.setting[0], 0);
    EXPECT_GT(quality::radiance_settings()[std::size_t(c.setting[3])].directions, 4);
}

TEST(RegionMaxError, AnImpossibleBoundTakesTheFinestAndSaysSo) {
    const quality::RegionChoice c = quality::choose_radiance_per_region(0.01, {0.1, 0.3}, {1, 2}, 10.0, false);
    EXPECT_FALSE(c.met);
    EXPECT_GT(c.predicted_error, 0.01);
    for (int k : c.setting) EXPECT_FALSE(quality::radiance_settings()[std::size_t(k)].exact_sun);
    EXPECT_THROW(quality::choose_radiance_per_region(0, {0.1}, {1}, 10.0, false), InputError);
}

}  // namespace
}  // namespace ts
