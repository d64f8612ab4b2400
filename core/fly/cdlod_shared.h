// The single definition of the CDLOD vertex morph and the Earth-curvature drop, shared by C++
// (core/fly/cdlod_tree.cpp, its tests) and GLSL (gpu/shaders/fly_terrain.vert). Written in the
// common subset of C++ and GLSL (core/util/glsl_compat.h), in float in both. GLSL: `#define
// TS_GLSL 1`, then include this file; C++: include cdlod_shared.hpp.
//
// Morph (Strugar 2010, "Continuous Distance-Dependent Level of Detail"): a patch of level k
// has vertices every 2^k texels; in its morph band [morph_start, morph_end] (metres from the
// eye) each odd vertex slides onto its even neighbour, so at morph_end the patch is exactly
// the level k+1 surface and meets a level k+1 neighbour without a crack.
#ifndef TS_CDLOD_SHARED_H
#define TS_CDLOD_SHARED_H

#include "core/util/glsl_compat.h"

// Earth radius with standard refraction (R / (1 - 0.13)), as core/render/perspective_view.hpp.
#define TS_FLY_EFFECTIVE_EARTH_RADIUS_M 7321644.0

// 0 before the band, 1 after it, linear inside.
TS_INLINE float ts_cdlod_morph_factor(float distance_m, float morph_start_m, float morph_end_m) {
    float t = (distance_m - morph_start_m) / max(morph_end_m - morph_start_m, float(1e-3));
    return clamp(t, float(0), float(1));
}

// A patch-grid index (0..N, an integer in float) moved towards the even index below it by
// `morph`: even indices stay, odd ones reach index - 1 at morph = 1.
TS_INLINE float ts_cdlod_morph_index(float index, float morph) {
    float odd = index - float(2) * floor(index * float(0.5));
    return index - odd * morph;
}

// How far the ground at horizontal distance s (metres) from the eye sits below the eye's
// tangent plane: s^2 / (2 R_eff).
TS_INLINE float ts_curvature_drop(float horizontal_distance_sq_m2) {
    return horizontal_distance_sq_m2 / float(2.0 * TS_FLY_EFFECTIVE_EARTH_RADIUS_M);
}

#endif  // TS_CDLOD_SHARED_H
