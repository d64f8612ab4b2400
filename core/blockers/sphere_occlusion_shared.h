// The single definition of what a bounding sphere hides from a receiver, shared by C++
// (core/blockers/sun_disc_occlusion.cpp, the terrain's and the meshes' sun shadows on the CPU)
// and GLSL (gpu/shaders/fly_terrain.frag, fly_aircraft.frag: the flying aircraft's shadows).
// Written in the common subset of C++ and GLSL (core/util/glsl_compat.h): double in C++, float
// in GLSL. GLSL: `#define TS_GLSL 1`, then include this file; C++: include
// sphere_occlusion_shared.hpp.
//
// Sun: seen from the receiver the sphere is a cap of angular radius theta_b = asin(r/d) and the
// sun a disc of angular radius alpha whose centre lies delta from the cap's centre. In the
// azimuthal equidistant projection about the cap's centre the cap is exactly a disc of radius
// theta_b and the sun, alpha << 1, a disc of radius alpha at distance delta (its sideways
// stretch sin(delta)/delta changes the covered fraction by O(alpha delta), below 1e-3 for any
// cap up to a hemisphere); the covered fraction is the area of two overlapping discs over
// pi alpha^2. Several spheres combine as prod (1 - covered_b) (exact for one; a little dark
// where partial covers overlap; umbrae exact).
//
// Sky: the fraction of a receiver's cosine-weighted hemisphere a sphere hides is the sphere's
// form factor: sin^2(theta_b) cos(beta) while its cap is wholly above the tangent plane (beta
// the angle between the normal and the sphere's centre), and Snyder's closed form ("Area light
// sources for real-time graphics", 1996) while the cap straddles it.
#ifndef TS_SPHERE_OCCLUSION_SHARED_H
#define TS_SPHERE_OCCLUSION_SHARED_H

#include "core/util/glsl_compat.h"

// phi - sin(phi), by its series where the difference would cancel (float, small segments).
TS_INLINE TS_REAL ts_phi_minus_sin(TS_REAL phi) {
    if (phi < TS_REAL(0.5)) {
        TS_REAL p2 = phi * phi;
        return phi * p2 *
               (TS_REAL(1.0 / 6.0) -
                p2 * (TS_REAL(1.0 / 120.0) -
                      p2 * (TS_REAL(1.0 / 5040.0) - p2 * (TS_REAL(1.0 / 362880.0) - p2 * TS_REAL(1.0 / 39916800.0)))));
    }
    return phi - sin(phi);
}

// Area of the segment a chord cuts off a disc of radius r, h (0..2r) its height (sagitta):
// r^2 / 2 (2 theta - sin 2 theta), theta the half-angle the chord subtends at the centre.
TS_INLINE TS_REAL ts_disc_segment_area(TS_REAL r, TS_REAL h) {
    h = clamp(h, TS_REAL(0), TS_REAL(2) * r);
    TS_REAL theta = atan(sqrt(h * (TS_REAL(2) * r - h)), r - h);
    return TS_REAL(0.5) * r * r * ts_phi_minus_sin(TS_REAL(2) * theta);
}

// Area shared by two discs of radii a and b whose centres are d apart.
TS_INLINE TS_REAL ts_disc_overlap_area(TS_REAL a, TS_REAL b, TS_REAL d) {
    if (d >= a + b) return TS_REAL(0);
    TS_REAL small_r = min(a, b);
    TS_REAL full = TS_REAL(TS_PI) * small_r * small_r;
    if (d <= abs(a - b)) return full;
    // Two circular segments cut by the common chord, at x_a from a's centre (signed: negative
    // when the chord lies beyond it). Written with the segments' heights, (d - b)(d + b) and
    // b - d, so float does not cancel where a small disc crosses a large one's edge.
    TS_REAL x_a = ((d - b) * (d + b) + a * a) / (TS_REAL(2) * d);
    TS_REAL h_a = a - x_a, h_b = (b - d) + x_a;
    return clamp(ts_disc_segment_area(a, h_a) + ts_disc_segment_area(b, h_b), TS_REAL(0), full);
}

// Fraction of a disc of angular radius sun_radius centred `separation` (radians) from the centre
// of a cap of half-angle cap_radius that the cap covers, in [0, 1].
TS_INLINE TS_REAL ts_sun_disc_covered_fraction(TS_REAL sun_radius, TS_REAL cap_radius, TS_REAL separation) {
    if (separation >= cap_radius + sun_radius) return TS_REAL(0);
    if (separation <= cap_radius - sun_radius) return TS_REAL(1);
    return ts_disc_overlap_area(sun_radius, cap_radius, separation) / (TS_REAL(TS_PI) * sun_radius * sun_radius);
}

// The fraction of the sun's disc (unit direction `sun` towards its centre, angular radius
// sun_radius) that a sphere hides from `receiver`: 1 inside the sphere.
TS_INLINE TS_REAL ts_sphere_sun_cover(TS_VEC3 center, TS_REAL radius, TS_VEC3 receiver, TS_VEC3 sun,
                                      TS_REAL sun_radius) {
    TS_VEC3 v = center - receiver;
    TS_REAL d = length(v);
    if (d <= radius) return TS_REAL(1);
    TS_REAL cap = asin(radius / d);
    // The angle between two unit vectors by atan2 keeps its precision near 0 (acos does not).
    TS_VEC3 u = v / d;
    TS_REAL separation = atan(length(cross(u, sun)), dot(u, sun));
    return ts_sun_disc_covered_fraction(sun_radius, cap, separation);
}

// The fraction of the cosine-weighted hemisphere about the unit `normal` at `receiver` that a
// sphere hides (its form factor), in [0, 1]: 1 inside the sphere, 0 wholly below the plane.
TS_INLINE TS_REAL ts_sphere_sky_cover(TS_VEC3 center, TS_REAL radius, TS_VEC3 receiver, TS_VEC3 normal) {
    TS_VEC3 v = center - receiver;
    TS_REAL d2 = dot(v, v);
    if (d2 <= radius * radius) return TS_REAL(1);
    TS_REAL s2 = radius * radius / d2;          // sin^2 of the cap's half-angle
    TS_REAL c = dot(v, normal) / sqrt(d2);      // cos of the angle between normal and centre
    if (c * c > s2) return c > TS_REAL(0) ? s2 * c : TS_REAL(0);
    // The cap straddles the tangent plane (Snyder 1996; as Lagarde & de Rousiers 2014 write it).
    TS_REAL sin_b = sqrt(max(TS_REAL(1) - c * c, TS_REAL(1e-12)));
    TS_REAL x = sqrt(max(TS_REAL(1) / s2 - TS_REAL(1), TS_REAL(0)));
    TS_REAL y = clamp(-x * c / sin_b, TS_REAL(-1), TS_REAL(1));
    TS_REAL w = sin_b * sqrt(max(TS_REAL(1) - y * y, TS_REAL(0)));
    TS_REAL e = (c * acos(y) - x * w) * s2 + atan(w, x);
    return clamp(e / TS_REAL(TS_PI), TS_REAL(0), TS_REAL(1));
}

// Several spheres' sky covers as one: their caps taken as patches scattered independently over
// the cap of a sphere holding them all (`bound_cover`, its ts_sphere_sky_cover), so overlapping
// spheres do not count twice: bound_cover (1 - prod_b (1 - min(1, cover_b / bound_cover))). It is
// at most the bound's cover and at most the sum of the covers, and tends to the sum for caps
// small against the bound's. Accumulate `product` (start at 1) with ts_sky_cover_step.
TS_INLINE TS_REAL ts_sky_cover_step(TS_REAL product, TS_REAL cover, TS_REAL bound_cover) {
    return bound_cover > TS_REAL(0) ? product * (TS_REAL(1) - min(TS_REAL(1), cover / bound_cover)) : product;
}
TS_INLINE TS_REAL ts_sky_cover_union(TS_REAL product, TS_REAL bound_cover) {
    return bound_cover * (TS_REAL(1) - product);
}

// The share of a receiver's sky term that blockers covering `cover` of its cosine-weighted
// hemisphere remove, when its terrain lets it see `open_sky` of that hemisphere
// (core/render/open_sky_fraction.hpp) and the blockers stand in the open part (an aircraft
// above a valley): cover / open_sky of the sky light the terrain leaves, under a sky of even
// radiance, and all of it once they cover that much. The floor keeps a receiver whose sky is
// nearly all hidden from dividing by ~0.
TS_INLINE TS_REAL ts_open_sky_share(TS_REAL cover, TS_REAL open_sky) {
    return min(TS_REAL(1), cover / max(open_sky, TS_REAL(0.05)));
}

#endif  // TS_SPHERE_OCCLUSION_SHARED_H
