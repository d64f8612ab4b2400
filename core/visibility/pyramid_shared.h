// The single definition of the pyramid method's per-sample math (core/visibility/
// pyramid_horizons.cpp), shared by C++ (in double, through pyramid_shared.hpp) and GLSL (in
// float, gpu/shaders/vis_pyramid_*.comp). The surface between texels, the void-skipping blend,
// is core/terrain/valid_bilinear_shared.h. Written in the common subset of C++ and GLSL
// (core/util/glsl_compat.h). GLSL: `#define TS_GLSL 1`, then include this file.
#ifndef TS_PYRAMID_SHARED_H
#define TS_PYRAMID_SHARED_H

#include "core/util/glsl_compat.h"

// The slope (tan of the elevation, less the Earth-curvature drop d^2 * curvature) of a height
// z seen from a receiver at z0 over ground distance s. With z the grid's highest height it is
// the bound past which a march can stop: it falls with s, so no farther sample can beat it.
TS_INLINE TS_REAL ts_pyramid_slope(TS_REAL z, TS_REAL z0, TS_REAL s, TS_REAL curvature) {
    return (z - z0) / s - curvature * s;
}

// The level a sample tau texels from the receiver reads: the one whose texel matches the gap
// to the next sample, tau * (ratio - 1) with ratio = 2^(1 / samples per octave).
TS_INLINE int ts_pyramid_sample_level(TS_REAL tau, TS_REAL ratio, int levels) {
    TS_REAL gap = tau * (ratio - 1.0);
    return clamp(int(floor(log2(max(gap, TS_REAL(1.0))))), 0, levels - 1);
}

#endif  // TS_PYRAMID_SHARED_H
