#pragma once
// How much of the sun's disc a sphere hides, analytically, for crisp sun shadows with the
// penumbra of the 0.53 degree disc (the method's "outside the blocker spheres, tested
// analytically"; docs/blockers.md).
//
// Seen from the receiver the sphere is a cap of angular radius theta_b = asin(r/d) and the sun
// a disc of angular radius alpha whose centre lies delta from the cap's centre. In the
// azimuthal equidistant projection about the cap's centre the cap is exactly a disc of radius
// theta_b and the sun, alpha << 1, a disc of radius alpha at distance delta (its sideways
// stretch sin(delta)/delta changes the covered fraction by O(alpha delta), below 1e-3 for any
// cap up to a hemisphere); the covered fraction is then the area of two overlapping discs
// over pi alpha^2. The formulas are sphere_occlusion_shared.h, the text the flythrough's shaders
// compile too.
#include <glm/vec3.hpp>

#include "core/blockers/sphere_blocker.hpp"

namespace ts::blockers {

// The sun's angular radius, 0.2667 degrees (as visibility::SunSweepOptions::sun_radius_rad).
inline constexpr double kSunAngularRadiusRad = 0.004654;

// Area shared by two discs of radii a and b whose centres are `distance` apart.
double disc_overlap_area(double a, double b, double distance);

// Fraction of a disc of angular radius sun_radius centred `separation` (radians) from the centre
// of a cap of half-angle cap_radius that the cap covers, in [0, 1]. cap_radius >= pi/2 - tiny
// and receivers inside the sphere (cap_radius = pi) are handled: the cap then covers all the
// directions within cap_radius.
double sun_disc_covered_fraction(double sun_radius, double cap_radius, double separation);

// The fraction of the sun's disc (unit direction `sun` towards its centre) that `sphere`
// hides from `receiver`.
double sphere_sun_cover(const Sphere& sphere, const glm::dvec3& receiver, const glm::dvec3& sun,
                        double sun_radius = kSunAngularRadiusRad);

// The fraction of the cosine-weighted hemisphere about the unit `normal` at `receiver` that
// `sphere` hides (its form factor; 1 inside it).
double sphere_sky_cover(const Sphere& sphere, const glm::dvec3& receiver, const glm::dvec3& normal);

}  // namespace ts::blockers
