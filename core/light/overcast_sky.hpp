#pragma once
// CIE standard overcast sky (Moon & Spencer 1942; CIE S 011/E:2003 sky type 1):
//   L(theta) = L_z (1 + 2 cos theta) / 3,
// zenith three times brighter than the horizon, no sun disc, white (equal RGB, so luminance = L).
// The zenith luminance follows the sun's elevation h as in Krochmann's fit for overcast skies
// (CIE 110-1994): L_z = 0.123 + 8.6 sin h kcd/m^2 for h in [0, 90] degrees, fading linearly
// from 0.123 to 0 between h = 0 and -6 degrees (civil twilight, as the clear sky), times the
// user's brightness factor. Horizontal illuminance of the dome: 7 pi / 9 L_z.
#include "core/light/sky.hpp"

namespace ts::light {

// Krochmann's overcast zenith luminance (kcd/m^2) for a sun elevation in degrees (with the
// twilight fade below the horizon).
double overcast_zenith_luminance(double sun_elevation_deg);

class OvercastSky final : public Sky {
public:
    OvercastSky(double brightness, double ground_albedo, const glm::dvec3& sun_direction_enu);

    Rgb radiance(const glm::dvec3& dir) const override;
    SunDisc sun() const override { return sun_; }  // irradiance 0: the sun is hidden
    std::string describe() const override;

    double zenith_luminance() const { return zenith_; }
    // The dome's horizontal illuminance, 7 pi / 9 L_z.
    double horizontal_illuminance() const;

private:
    double zenith_;
    double albedo_;
    SunDisc sun_;
};

}  // namespace ts::light
