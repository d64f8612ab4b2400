// The diffuse sky of the insolation maps (period_sky.hpp): the CIE clear sky summed over a period
// and seen through a texel's horizons, against the quadrature of the reference, an open plane's
// ESRA diffuse, and what makes it anisotropic (docs/insolation.md, "Diffuse").
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/solar/cie_clear_sky.hpp"
#include "core/solar/esra_clear_sky.hpp"
#include "core/solar/insolation_model.hpp"
#include "core/solar/insolation_reference.hpp"
#include "core/solar/period_sky.hpp"
#include "core/solar/sun_path.hpp"
#include "core/util/angles.hpp"

namespace ts::solar {
namespace {

InsolationSettings days(CalendarDate first, CalendarDate last, double step_minutes) {
    InsolationSettings s;
    s.periods = make_periods(first, last, PeriodSplit::year, 0.0);
    s.linke_monthly.fill(3.0);
    s.step_minutes = step_minutes;
    s.threads = 1;
    s.azimuth_bins = 256;
    s.svf_stride = 4;  // 64 sky sectors on 64 horizon azimuths
    return s;
}

std::vector<float> texel(const InsolationModel& m, const std::vector<float>& bins, glm::dvec3 n) {
    std::vector<float> out(std::size_t(m.periods()) * kQuantities);
    m.texel(bins.data(), glm::vec3(glm::normalize(n)), 0, 0.0, out.data());
    return out;
}

// 64 horizon azimuths to the model's 256 bins (each bin holds its azimuth's horizon, as
// integrate_insolation's interpolation does between equal neighbours).
std::vector<float> bins_of(const std::vector<float>& h64) {
    std::vector<float> b(256);
    for (int j = 0; j < 256; ++j) {
        const int d = j / 4;
        const float f = float(j % 4) / 4.0f;
        b[std::size_t(j)] = h64[std::size_t(d)] + f * (h64[std::size_t((d + 1) % 64)] - h64[std::size_t(d)]);
    }
    return b;
}

TEST(CieClearSky, BrightensAroundTheSunAndTowardsTheHorizon) {
    const glm::dvec3 sun(std::cos(radians(30.0)), 0, std::sin(radians(30.0)));
    const glm::dvec3 zenith(0, 0, 1), near_sun(std::cos(radians(35.0)), 0, std::sin(radians(35.0)));
    const glm::dvec3 away_high(-std::cos(radians(60.0)), 0, std::sin(radians(60.0)));
    const glm::dvec3 away_low(-std::cos(radians(10.0)), 0, std::sin(radians(10.0)));
    EXPECT_GT(cie_clear_sky_radiance(sun, near_sun), 3 * cie_clear_sky_radiance(sun, zenith));
    // Away from the sun, brighter near the horizon (the gradation) than higher up.
    EXPECT_GT(cie_clear_sky_radiance(sun, away_low), cie_clear_sky_radiance(sun, away_high));
    // The classic form 0.91 + 10 exp(-3 chi) + 0.45 cos^2 chi at the zenith under a 90 degree sun.
    EXPECT_NEAR(cie_clear_sky_indicatrix(1.0), 0.91 + 10 + 0.45, 0.002);
    EXPECT_NEAR(cie_clear_sky_gradation(1.0), 1 - std::exp(-0.32), 1e-12);
}

// The kernel's normalisation: every sun elevation's sky gives a horizontal plane exactly its
// ESRA diffuse, so an open flat texel's diffuse is ESRA's diffuse summed step by step.
TEST(PeriodSky, OpenFlatPlaneReceivesEsraDiffuseExactly) {
    for (double lat : {0.0, 45.0, 70.0}) {
        const InsolationSettings s = days({2024, 3, 1}, {2024, 3, 10}, 5.0);
        const InsolationModel m(s, lat, lat, 0.1, 0, 0, 500.0);
        const auto out = texel(m, std::vector<float>(256, -0.05f), {0, 0, 1});
        double esra = 0;
        for (const EphemerisSample& e : sample_sun_path(s.periods, s.step_minutes, 0.0)) {
            const LocalSun sun = local_sun(e, lat, 0.0, s.refraction);
            if (!(sun.elevation_rad > 0)) continue;
            esra += diffuse_horizontal_irradiance(extraterrestrial_normal_irradiance(e.day_of_year), 3.0, sun.altitude_rad) *
                    e.hours;
        }
        // The sky below the horizontal (horizons at -3 degrees) is behind a flat texel's plane.
        EXPECT_NEAR(out[kDiffuse] / (esra / 1000), 1.0, 2e-3) << "latitude " << lat;
    }
}

// Tables against the reference's quadrature (every step, 48 elevations per azimuth) under
// horizons that hide different parts of the sky, on slopes: the binning of the sun's elevation
// and azimuth, the sectors and the 1-degree cells cost well under 1%.
TEST(PeriodSky, TablesMatchTheStepByStepQuadrature) {
    const InsolationSettings s = days({2024, 12, 10}, {2024, 12, 12}, 4.0);
    const InsolationModel m(s, 45, 45, 0.1, 0, 0, 500.0);
    struct Case {
        const char* what;
        glm::dvec3 n;
        std::vector<float> h64;
    };
    std::vector<Case> cases;
    std::vector<float> south_wall(64, 0.02f), ridge(64), valley(64);
    for (int d = 0; d < 64; ++d) {
        const double phi = 2 * kPi * d / 64;  // counter-clockwise from east; south at 3 pi / 2
        if (std::sin(phi) < -0.3) south_wall[std::size_t(d)] = float(radians(18.0));
        ridge[std::size_t(d)] = float(radians(-4.0 + 2.0 * std::cos(phi)));
        valley[std::size_t(d)] = float(radians(25.0 + 10.0 * std::sin(2 * phi)));
    }
    cases.push_back({"flat under a southern wall", {0, 0, 1}, south_wall});
    cases.push_back({"south slope under a southern wall", {0, -0.5, 1}, south_wall});
    cases.push_back({"north slope on a ridge", {0.2, 0.6, 1}, ridge});
    cases.push_back({"east slope in a valley", {0.7, 0, 1}, valley});
    for (const Case& c : cases) {
        const auto fast = texel(m, bins_of(c.h64), c.n);
        ReferenceSky sky;
        sky.elevations = 48;
        const auto ref = reference_insolation(s, 45, 0.0, glm::normalize(c.n), c.h64, sky);
        std::printf("%s: tables / quadrature - 1 = %+.3f%%\n", c.what, 100 * (fast[kDiffuse] / ref[kDiffuse] - 1));
        EXPECT_NEAR(fast[kDiffuse] / ref[kDiffuse], 1.0, 0.006) << c.what;
    }
}

// What an isotropic sky cannot tell apart: two slopes with the same sky view, one facing the
// winter sun and one away from it; a wall on the sun's side against the same wall opposite.
TEST(PeriodSky, TheSkyIsBrighterOnTheSunsSide) {
    const InsolationSettings s = days({2024, 12, 1}, {2024, 12, 31}, 10.0);
    const InsolationModel m(s, 45, 45, 0.1, 0, 0, 500.0);
    const auto south = texel(m, std::vector<float>(256, 0.0f), {0, -0.6, 1});
    const auto north = texel(m, std::vector<float>(256, 0.0f), {0, 0.6, 1});
    std::printf("December at 45 N: diffuse facing south / north %.3f\n", south[kDiffuse] / north[kDiffuse]);
    EXPECT_GT(south[kDiffuse], 1.3 * north[kDiffuse]);
    std::vector<float> wall_south(64, 0.0f), wall_north(64, 0.0f);
    for (int d = 0; d < 64; ++d) {
        const double y = std::sin(2 * kPi * d / 64);
        if (y < -0.5) wall_south[std::size_t(d)] = float(radians(30.0));
        if (y > 0.5) wall_north[std::size_t(d)] = float(radians(30.0));
    }
    const auto under_south = texel(m, bins_of(wall_south), {0, 0, 1});
    const auto under_north = texel(m, bins_of(wall_north), {0, 0, 1});
    std::printf("under a 30 degree wall to the south / to the north %.3f\n", under_south[kDiffuse] / under_north[kDiffuse]);
    EXPECT_LT(under_south[kDiffuse], 0.9 * under_north[kDiffuse]);
}

}  // namespace
}  // namespace ts::solar
