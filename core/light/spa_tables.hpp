#pragma once
// The data tables of the NREL Solar Position Algorithm (Reda & Andreas, "Solar position
// algorithm for solar radiation applications", NREL/TP-560-34302, 2003, rev. 2008; Solar
// Energy 76(5), 2004): Tables A4.2 (Earth periodic terms, from VSOP87) and A4.3 (periodic
// terms for the nutation in longitude and obliquity). Kept apart from the algorithm so the
// numbers can be checked against the paper line by line.
#include <span>

namespace ts::light::spa {

// One periodic term A * cos(B + C * JME) of an Earth heliocentric series (A in 1e-8 rad or
// 1e-8 AU, B in radians, C in radians per Julian millennium).
struct EarthTerm {
    double a, b, c;
};

// The series L0..L5 (longitude), B0..B1 (latitude), R0..R4 (radius vector).
std::span<const std::span<const EarthTerm>> earth_longitude_series();
std::span<const std::span<const EarthTerm>> earth_latitude_series();
std::span<const std::span<const EarthTerm>> earth_radius_series();

// One row of the nutation table: multipliers Y0..Y4 of the arguments X0..X4 (mean elongation
// of the Moon from the Sun, mean anomalies of the Sun and the Moon, the Moon's argument of
// latitude, longitude of the Moon's ascending node), and the coefficients of
// delta psi = (a + b * JCE) sin(sum) and delta epsilon = (c + d * JCE) cos(sum), in 0.0001".
struct NutationTerm {
    int y[5];
    double a, b, c, d;
};

std::span<const NutationTerm> nutation_terms();

}  // namespace ts::light::spa
