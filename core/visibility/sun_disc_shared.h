// The single definition of the sun disc's visible fraction above a horizon line, in the common
// subset of C++ and GLSL (core/util/glsl_compat.h): the CPU's sun visibility (sun_visibility.cpp)
// and the flythrough's per-fragment sun (gpu/fly/fly_terrain_frag.glsl) compile this text.
// C++: include core/visibility/sun_disc_shared.hpp. GLSL: `#define TS_GLSL 1`, then this file.
#ifndef TS_SUN_DISC_SHARED_H
#define TS_SUN_DISC_SHARED_H

#include "core/util/glsl_compat.h"

// x: the height of the disc's centre above the horizon line, in disc radii ((e - h) / r). The
// part below the line is the circular segment of height 1 - x, of area acos(x) - x sqrt(1 - x^2)
// for a unit radius; the fraction is what is left of pi.
TS_INLINE TS_REAL ts_sun_disc_fraction(TS_REAL x) {
    if (x >= TS_REAL(1.0)) return TS_REAL(1.0);
    if (x <= TS_REAL(-1.0)) return TS_REAL(0.0);
    TS_REAL below = (acos(x) - x * sqrt(TS_REAL(1.0) - x * x)) / TS_REAL(TS_PI);
    return clamp(TS_REAL(1.0) - below, TS_REAL(0.0), TS_REAL(1.0));
}

#endif  // TS_SUN_DISC_SHARED_H
