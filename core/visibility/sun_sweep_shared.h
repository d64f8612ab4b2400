// The single definition of the shadow-height recursion of the sun sweep (sun_sweep.cpp), in
// the common subset of C++ and GLSL (core/util/glsl_compat.h), so a GPU kernel can reuse it.
// C++: include core/visibility/sun_sweep_shared.hpp. GLSL: `#define TS_GLSL 1`, then this file.
//
// Along a line of constant azimuth walked away from the sun, the shadow height S at a point is
// the highest of z_k - d_k (tan e + c d_k), over the occluders k at ground distance d_k behind
// it (e the sun's elevation, c = 1 / (2 R_eff) the curvature drop factor, earth_curvature.hpp):
// a point of height z is lit iff z >= S. Each line keeps S with the distance d of the occluder
// that sets it, so one step of ds lowers S by the drop below and a new occluder competes with
// ts_shadow_height; the horizon tangent that occluder gives is ts_shadow_tangent.
#ifndef TS_SUN_SWEEP_SHARED_H
#define TS_SUN_SWEEP_SHARED_H

#include "core/util/glsl_compat.h"

// Single precision on both sides: heights and distances are floats in the sweep's lines.
#define TS_SUN_REAL float

// Shadow height cast at distance d by an occluder of height z.
TS_INLINE TS_SUN_REAL ts_shadow_height(TS_SUN_REAL z, TS_SUN_REAL d, TS_SUN_REAL tan_e, TS_SUN_REAL curv) {
    return z - d * (tan_e + curv * d);
}

// How much a shadow height set by an occluder at distance d drops over a further step ds.
TS_INLINE TS_SUN_REAL ts_shadow_drop(TS_SUN_REAL d, TS_SUN_REAL ds, TS_SUN_REAL tan_e, TS_SUN_REAL curv) {
    return ds * (tan_e + curv * (d + d + ds));
}

// tan(elevation) of that occluder seen from a point of height z: (z_k - z - c d^2) / d.
TS_INLINE TS_SUN_REAL ts_shadow_tangent(TS_SUN_REAL shadow, TS_SUN_REAL z, TS_SUN_REAL d, TS_SUN_REAL tan_e) {
    return tan_e + (shadow - z) / d;
}

#endif  // TS_SUN_SWEEP_SHARED_H
