// Equation numbers refer to Reda & Andreas, NREL/TP-560-34302 (2008 revision), section 3.
#include "core/light/sun_position.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/geo/azimuth.hpp"
#include "core/light/delta_t.hpp"
#include "core/light/spa_tables.hpp"
#include "core/util/angles.hpp"
#include "core/util/error.hpp"

namespace ts::light {

namespace {

// Degrees to radians as a division by 180 / pi, as this code always did: radians() multiplies
// by pi / 180, which differs in the last bit for some angles.
double rad(double deg) {
    return deg / degrees(1.0);
}
double deg(double r) {
    return degrees(r);
}

// Angle in [0, 360).
double wrap_360(double d) {
    d = std::fmod(d, 360.0);
    return d < 0.0 ? d + 360.0 : d;
}

// Eq. 9-11: a heliocentric quantity from its series, sum_i (sum_j A cos(B + C JME)) JME^i / 1e8.
double series(std::span<const std::span<const spa::EarthTerm>> terms, double jme) {
    double total = 0.0, power = 1.0;
    for (const auto& row : terms) {
        double sum = 0.0;
        for (const spa::EarthTerm& t : row) sum += t.a * std::cos(t.b + t.c * jme);
        total += sum * power;
        power *= jme;
    }
    return total / 1e8;
}

double cubic(double a, double b, double c, double d, double x) {
    return a + x * (b + x * (c + x * d));
}

struct Nutation {
    double longitude_deg, obliquity_deg;
};

// Eq. 15-23: nutation in longitude and obliquity from the 63-term series.
Nutation nutation(double jce) {
    const double x[5] = {
        cubic(297.85036, 445267.111480, -0.0019142, 1.0 / 189474.0, jce),  // mean elongation Moon-Sun
        cubic(357.52772, 35999.050340, -0.0001603, -1.0 / 300000.0, jce),  // mean anomaly of the Sun
        cubic(134.96298, 477198.867398, 0.0086972, 1.0 / 56250.0, jce),    // mean anomaly of the Moon
        cubic(93.27191, 483202.017538, -0.0036825, 1.0 / 327270.0, jce),   // Moon's argument of latitude
        cubic(125.04452, -1934.136261, 0.0020708, 1.0 / 450000.0, jce),    // Moon's ascending node
    };
    double psi = 0.0, eps = 0.0;
    for (const spa::NutationTerm& t : spa::nutation_terms()) {
        double arg = 0.0;
        for (int j = 0; j < 5; ++j) arg += x[j] * t.y[j];
        arg = rad(arg);
        psi += (t.a + t.b * jce) * std::sin(arg);
        eps += (t.c + t.d * jce) * std::cos(arg);
    }
    return {psi / 36000000.0, eps / 36000000.0};  // 0.0001 arcsec -> degrees
}

// Eq. 24: mean obliquity of the ecliptic in arcseconds (Laskar 1986), U = JME / 10.
double mean_obliquity_arcsec(double jme) {
    constexpr double kCoefficients[] = {84381.448, -4680.93, -1.55, 1999.25, -51.38, -249.67,
                                        -39.05,    7.12,     27.87, 5.79,    2.45};
    const double u = jme / 10.0;
    double result = 0.0;
    for (int i = 10; i >= 0; --i) result = result * u + kCoefficients[i];
    return result;
}

void check_input(const SunPositionInput& in) {
    const Observer& o = in.observer;
    const auto fail = [](const std::string& problem) { throw input_error("sun position", problem); };
    if (!std::isfinite(o.latitude_deg) || o.latitude_deg < -90.0 || o.latitude_deg > 90.0)
        fail("latitude " + std::to_string(o.latitude_deg) + " is outside [-90, 90]");
    if (!std::isfinite(o.longitude_deg)) fail("longitude is not a finite number");
    if (!std::isfinite(o.height_m) || o.height_m < -6500000.0) fail("height is below -6500 km or not finite");
    if (!(in.atmosphere.pressure_hpa >= 0.0 && in.atmosphere.pressure_hpa <= 5000.0))
        fail("pressure " + std::to_string(in.atmosphere.pressure_hpa) + " hPa is outside [0, 5000]");
    if (!(in.atmosphere.temperature_c > -273.0 && in.atmosphere.temperature_c <= 6000.0))
        fail("temperature " + std::to_string(in.atmosphere.temperature_c) + " C is outside (-273, 6000]");
    if (in.delta_t_s && !(std::abs(*in.delta_t_s) <= 8000.0))
        fail("delta T " + std::to_string(*in.delta_t_s) + " s is outside [-8000, 8000]");
    if (!(std::abs(in.delta_ut1_s) < 1.0)) fail("delta UT1 must be within (-1, 1) s");
    const double year = decimal_year(in.time);
    if (year < -2000.0 || year >= 6001.0) fail("year outside -2000..6000, the algorithm's validity range");
}

}  // namespace

Atmosphere Atmosphere::standard_at(double height_m) {
    // ICAO troposphere: T = 288.15 - 0.0065 h, p = 1013.25 (T / 288.15)^5.25588 (valid below 11 km;
    // above it the tropopause value is kept, enough for refraction).
    const double h = std::clamp(height_m, -500.0, 11000.0);
    const double kelvin = 288.15 - 0.0065 * h;
    return {1013.25 * std::pow(kelvin / 288.15, 5.25588), kelvin - 273.15};
}

double refraction_correction_deg(double e0, const Atmosphere& atm) {
    // Eq. 42: Saemundsson (1986) for the unrefracted elevation, arcminutes -> degrees.
    const auto saemundsson = [&](double e) {
        return (atm.pressure_hpa / 1010.0) * (283.0 / (273.0 + atm.temperature_c)) * 1.02 /
               (60.0 * std::tan(rad(e + 10.3 / (e + 5.11))));
    };
    const double threshold = -(kSunRadiusDeg + kHorizonRefractionDeg);
    if (e0 >= threshold) return saemundsson(e0);
    // The SPA stops refracting here, where a sea-level observer's sun has set: the sun would drop
    // 0.6 degree from one minute to the next, and a peak, whose horizon lies lower, would see
    // its light go out at once. Faded instead, linearly to nothing at kRefractionEndDeg (where
    // the formula nears its pole at -5.11): continuous, and the apparent sun still sinks.
    if (e0 <= kRefractionEndDeg) return 0.0;
    return saemundsson(threshold) * (e0 - kRefractionEndDeg) / (threshold - kRefractionEndDeg);
}

SunPosition sun_position(const SunPositionInput& in) {
    check_input(in);
    SunPosition s;
    // 3.1 Julian dates (eq. 4-8).
    s.delta_t_s = in.delta_t_s ? *in.delta_t_s : default_delta_t(in.time);
    s.julian_day = julian_day(in.time) + in.delta_ut1_s / 86400.0;
    s.julian_ephemeris_day = s.julian_day + s.delta_t_s / 86400.0;
    const double jc = (s.julian_day - 2451545.0) / 36525.0;
    const double jce = (s.julian_ephemeris_day - 2451545.0) / 36525.0;
    const double jme = jce / 10.0;

    // 3.2 Earth heliocentric longitude, latitude and radius vector (eq. 9-14).
    s.heliocentric_longitude_deg = wrap_360(deg(series(spa::earth_longitude_series(), jme)));
    s.heliocentric_latitude_deg = deg(series(spa::earth_latitude_series(), jme));
    s.earth_sun_distance_au = series(spa::earth_radius_series(), jme);

    // 3.3 Geocentric longitude and latitude of the sun (eq. 13-14).
    const double theta = wrap_360(s.heliocentric_longitude_deg + 180.0);
    const double beta = -s.heliocentric_latitude_deg;

    // 3.4-3.5 Nutation and the true obliquity of the ecliptic (eq. 15-25).
    const Nutation n = nutation(jce);
    s.nutation_longitude_deg = n.longitude_deg;
    s.nutation_obliquity_deg = n.obliquity_deg;
    s.true_obliquity_deg = mean_obliquity_arcsec(jme) / 3600.0 + n.obliquity_deg;

    // 3.6-3.7 Aberration and the apparent sun longitude (eq. 26-27).
    const double aberration = -20.4898 / (3600.0 * s.earth_sun_distance_au);
    s.apparent_sun_longitude_deg = theta + n.longitude_deg + aberration;

    // 3.8 Apparent sidereal time at Greenwich (eq. 28-29).
    const double nu0 = wrap_360(280.46061837 + 360.98564736629 * (s.julian_day - 2451545.0) + 0.000387933 * jc * jc -
                                jc * jc * jc / 38710000.0);
    s.apparent_sidereal_time_deg = nu0 + n.longitude_deg * std::cos(rad(s.true_obliquity_deg));

    // 3.9-3.10 Geocentric right ascension and declination (eq. 30-31).
    const double lambda = rad(s.apparent_sun_longitude_deg), eps = rad(s.true_obliquity_deg), b = rad(beta);
    s.right_ascension_deg =
        wrap_360(deg(std::atan2(std::sin(lambda) * std::cos(eps) - std::tan(b) * std::sin(eps), std::cos(lambda))));
    s.declination_deg = deg(std::asin(std::sin(b) * std::cos(eps) + std::cos(b) * std::sin(eps) * std::sin(lambda)));

    // 3.11 Observer local hour angle (eq. 32).
    s.observer_hour_angle_deg =
        wrap_360(s.apparent_sidereal_time_deg + in.observer.longitude_deg - s.right_ascension_deg);

    // 3.12 Topocentric right ascension and declination: parallax of the observer on the
    // ellipsoid at its height (eq. 33-38; 0.99664719 = 1 - flattening, 6378140 m = equatorial radius).
    const double phi = rad(in.observer.latitude_deg);
    const double xi = rad(8.794 / (3600.0 * s.earth_sun_distance_au));  // equatorial horizontal parallax
    const double u = std::atan(0.99664719 * std::tan(phi));
    const double x = std::cos(u) + in.observer.height_m / 6378140.0 * std::cos(phi);
    const double y = 0.99664719 * std::sin(u) + in.observer.height_m / 6378140.0 * std::sin(phi);
    const double h = rad(s.observer_hour_angle_deg), delta = rad(s.declination_deg);
    const double denominator = std::cos(delta) - x * std::sin(xi) * std::cos(h);
    const double delta_alpha = std::atan2(-x * std::sin(xi) * std::sin(h), denominator);
    const double delta_prime = std::atan2((std::sin(delta) - y * std::sin(xi)) * std::cos(delta_alpha), denominator);
    s.topocentric_declination_deg = deg(delta_prime);
    s.topocentric_hour_angle_deg = s.observer_hour_angle_deg - deg(delta_alpha);

    // 3.13-3.14 Topocentric elevation with refraction, and the zenith angle (eq. 41-44).
    const double h_prime = rad(s.topocentric_hour_angle_deg);
    s.elevation_unrefracted_deg = deg(
        std::asin(std::sin(phi) * std::sin(delta_prime) + std::cos(phi) * std::cos(delta_prime) * std::cos(h_prime)));
    s.elevation_deg =
        s.elevation_unrefracted_deg + refraction_correction_deg(s.elevation_unrefracted_deg, in.atmosphere);
    s.zenith_deg = 90.0 - s.elevation_deg;

    // 3.15 Azimuth (eq. 45-46): astronomers' azimuth (westward from south), then from north.
    const double gamma =
        deg(std::atan2(std::sin(h_prime), std::cos(h_prime) * std::sin(phi) - std::tan(delta_prime) * std::cos(phi)));
    s.azimuth_deg = wrap_360(gamma + 180.0);
    return s;
}

glm::dvec3 sun_direction_enu(const SunPosition& sun) {
    return geo::enu_direction(geo::azimuth_cw_from_north_to_phi(sun.azimuth_deg), rad(sun.elevation_deg));
}

double incidence_angle_deg(const SunPosition& sun, double slope_deg, double normal_azimuth_deg) {
    // Eq. 47 with both azimuths clockwise from north (their difference is the same as the SPA's).
    const double zenith = rad(sun.zenith_deg), slope = rad(slope_deg);
    const double c = std::cos(zenith) * std::cos(slope) +
                     std::sin(slope) * std::sin(zenith) * std::cos(rad(sun.azimuth_deg - normal_azimuth_deg));
    return deg(std::acos(std::clamp(c, -1.0, 1.0)));
}

}  // namespace ts::light
