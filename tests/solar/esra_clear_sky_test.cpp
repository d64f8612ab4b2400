#include "core/solar/esra_clear_sky.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/util/angles.hpp"

namespace ts::solar {
namespace {

TEST(EsraClearSky, BeamAndDiffuseAtThirtyDegreesMatchHandComputedValues) {
    // TL 3 at sea level, sun at 30 deg, G0 = 1367: m = 1.99255, deltaR = 0.103185 (computed by
    // hand from the formulas of docs/insolation.md), so B = 801.19 W/m^2; Tn = 0.0792033 and
    // Dh = 89.799 W/m^2.
    EXPECT_NEAR(relative_optical_air_mass(radians(30.0), 0.0), 1.99255, 1e-4);
    EXPECT_NEAR(rayleigh_optical_thickness(1.99255), 0.103185, 1e-5);
    EXPECT_NEAR(beam_normal_irradiance(1367.0, 3.0, radians(30.0), 0.0), 801.19, 0.02);
    EXPECT_NEAR(diffuse_transmission(3.0), 0.0792033, 1e-6);
    EXPECT_NEAR(diffuse_horizontal_irradiance(1367.0, 3.0, radians(30.0)), 89.799, 0.01);
}

TEST(EsraClearSky, AirMassFollowsPressureWithHeight) {
    const double m0 = relative_optical_air_mass(radians(40.0), 0.0);
    EXPECT_NEAR(relative_optical_air_mass(radians(40.0), 8434.5) / m0, std::exp(-1.0), 1e-12);
    // At the zenith the air mass is ~1 (Kasten & Young).
    EXPECT_NEAR(relative_optical_air_mass(radians(90.0), 0.0), 1.0, 1e-3);
}

TEST(EsraClearSky, RayleighThicknessIsNearlyContinuousAtTwenty) {
    EXPECT_NEAR(rayleigh_optical_thickness(20.0) / rayleigh_optical_thickness(20.0 + 1e-9), 1.0, 1e-3);
}

TEST(EsraClearSky, NothingBelowTheHorizonAndNoAtmosphereAtLinkeZero) {
    EXPECT_EQ(beam_normal_irradiance(1367.0, 3.0, -0.01, 0.0), 0.0);
    EXPECT_EQ(diffuse_horizontal_irradiance(1367.0, 3.0, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(beam_normal_irradiance(1367.0, 0.0, 0.3, 0.0), 1367.0);
}

TEST(EsraClearSky, EccentricityPeaksInEarlyJanuary) {
    EXPECT_NEAR(extraterrestrial_normal_irradiance(2.8408), 1367.0 * 1.03344, 1e-6);
    EXPECT_NEAR(extraterrestrial_normal_irradiance(2.8408 + 365.25 / 2), 1367.0 * 0.96656, 1e-6);
}

}  // namespace
}  // namespace ts::solar
