#pragma once
// The sun's path through the periods of an insolation map, sampled at a fine step: one
// geocentric ephemeris for every latitude (declination and Greenwich hour angle from the NREL
// SPA of core/light, evaluated every 20 minutes and interpolated linearly between, which
// changes the sun's position by less than 1e-5 degree), then per latitude the sun's direction
// in the local frame. Topocentric parallax (< 0.0025 degree) is left out.
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "core/solar/insolation_period.hpp"

namespace ts::solar {

// One time step: its midpoint's geocentric sun and the hours it stands for.
struct EphemerisSample {
    double declination_rad = 0;
    double greenwich_hour_angle_rad = 0;  // the SPA's observer hour angle at longitude 0
    double hours = 0;                     // the step's length
    int period = 0;                       // index into the periods
    int month0 = 0;                       // month (0..11) and day of year on the mean solar clock
    int day_of_year = 1;
};

// Every step of every period: a period of length L is cut into ceil(L / step) equal steps.
// `clock_longitude_deg`: the clock of months and days of year (insolation_period.hpp).
// Throws ts::InputError for a step outside (0, 60] minutes or an empty period.
std::vector<EphemerisSample> sample_sun_path(const std::vector<InsolationPeriod>& periods, double step_minutes,
                                             double clock_longitude_deg);

// The sun seen from a latitude and longitude at one sample.
struct LocalSun {
    glm::dvec3 direction;          // unit, ENU (x east, y north, z up), refracted when asked
    double altitude_rad = 0;       // unrefracted (what ESRA's air mass takes)
    double elevation_rad = 0;      // refracted when asked (what the horizon hides)
    double phi_rad = 0;            // internal azimuth, counter-clockwise from east, [0, 2 pi)
};
// refraction: the SPA's refraction correction at a standard atmosphere (1013.25 hPa, 15 C).
// grid_north_deg: where true north lies on the grid the direction is for (0: true north;
// Georef::grid_azimuth_of_north_deg on a projected grid); phi and direction are the grid's.
LocalSun local_sun(const EphemerisSample& s, double latitude_deg, double longitude_deg, bool refraction,
                   double grid_north_deg = 0.0);

}  // namespace ts::solar
