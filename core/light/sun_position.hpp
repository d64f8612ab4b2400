#pragma once
// The sun's topocentric position by the NREL Solar Position Algorithm (SPA): Reda & Andreas,
// "Solar position algorithm for solar radiation applications", Solar Energy 76(5) 577-589
// (2004), NREL/TP-560-34302 (rev. 2008). Stated uncertainty +-0.0003 deg for the years
// -2000..6000, given delta T. Steps: Julian dates, Earth heliocentric position (VSOP87
// periodic terms, spa_tables.cpp), geocentric sun, nutation, aberration, apparent sidereal
// time, geocentric right ascension/declination, topocentric parallax (observer height),
// atmospheric refraction.
#include <glm/vec3.hpp>
#include <optional>

#include "core/light/utc_time.hpp"

namespace ts::light {

// Where on the WGS84 ellipsoid the sun is seen from.
struct Observer {
    double latitude_deg = 0.0;   // geodetic, north positive, [-90, 90]
    double longitude_deg = 0.0;  // east positive; any finite value (wrapped)
    double height_m = 0.0;       // above the ellipsoid (the SPA's "elevation"); the geoid's 0..100 m do not matter
};

// The air that bends the sun's light near the horizon (refraction only).
struct Atmosphere {
    double pressure_hpa = 1013.25;  // at the observer (hPa = mbar); 0 turns refraction off
    double temperature_c = 15.0;    // at the observer, annual mean

    // The ICAO standard atmosphere at a height (1013.25 hPa and 15 C at sea level, a lapse of
    // 6.5 C/km): the default when the user gives neither.
    static Atmosphere standard_at(double height_m);
};

struct SunPositionInput {
    UtcTime time;
    Observer observer;
    Atmosphere atmosphere;
    std::optional<double> delta_t_s;  // TT - UT1 in seconds; empty: espenak_meeus_delta_t
    double delta_ut1_s = 0.0;         // UT1 - UTC in seconds (|x| < 0.9; IERS Bulletin A)
};

// The SPA's threshold for refraction: below -(sun radius + refraction at the horizon) the
// sun is wholly below the horizon and no refraction is applied, as in the SPA's reference code.
inline constexpr double kSunRadiusDeg = 0.26667;
inline constexpr double kHorizonRefractionDeg = 0.5667;

struct SunPosition {
    // The results.
    double azimuth_deg = 0.0;    // clockwise from north, [0, 360)
    double zenith_deg = 0.0;     // topocentric, refracted
    double elevation_deg = 0.0;  // 90 - zenith_deg
    double elevation_unrefracted_deg = 0.0;

    // Intermediate values, named as in the SPA paper, for checks against its published example.
    double julian_day = 0.0;                   // JD (UT)
    double julian_ephemeris_day = 0.0;         // JDE (TT)
    double delta_t_s = 0.0;                    // the delta T used
    double heliocentric_longitude_deg = 0.0;   // L
    double heliocentric_latitude_deg = 0.0;    // B
    double earth_sun_distance_au = 0.0;        // R
    double nutation_longitude_deg = 0.0;       // delta psi
    double nutation_obliquity_deg = 0.0;       // delta epsilon
    double true_obliquity_deg = 0.0;           // epsilon
    double apparent_sun_longitude_deg = 0.0;   // lambda
    double apparent_sidereal_time_deg = 0.0;   // nu (Greenwich)
    double right_ascension_deg = 0.0;          // alpha, geocentric
    double declination_deg = 0.0;              // delta, geocentric
    double observer_hour_angle_deg = 0.0;      // H, geocentric
    double topocentric_declination_deg = 0.0;  // delta'
    double topocentric_hour_angle_deg = 0.0;   // H'
};

// Throws ts::InputError for a latitude outside [-90, 90], a year outside -2000..6000, a
// pressure outside [0, 5000] hPa, a temperature outside (-273, 6000] C, |delta T| > 8000 s,
// |delta UT1| >= 1 s, or a height below -6500 km (the SPA's own input ranges), or non-finite input.
SunPosition sun_position(const SunPositionInput& input);

// The SPA's refraction correction (Saemundsson's formula with pressure and temperature), in
// degrees, for an unrefracted topocentric elevation. Below the threshold above, where the SPA
// gives 0, it fades linearly from the threshold's value to 0 at kRefractionEndDeg, so the sun
// sets and rises without a jump (a mountain still sees it there).
constexpr double kRefractionEndDeg = -5.0;
double refraction_correction_deg(double elevation_unrefracted_deg, const Atmosphere& atmosphere);

// The unit vector towards the sun in the local ENU frame (x east, y north, z up), from the
// azimuth clockwise from north and the (refracted) elevation (through core/geo/azimuth.hpp,
// the one place where user-facing azimuths become frame directions).
glm::dvec3 sun_direction_enu(const SunPosition& sun);

// Angle of incidence of the sun on a plane tilted by slope_deg whose downhill normal points to
// normal_azimuth_deg (clockwise from north), e.g. the SPA example's surface: slope 30, facing
// 10 deg east of south = azimuth 170.
double incidence_angle_deg(const SunPosition& sun, double slope_deg, double normal_azimuth_deg);

}  // namespace ts::light
