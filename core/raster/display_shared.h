// The single definition of the display transform of every 8-bit picture, in the common subset
// of C++ and GLSL (core/util/glsl_compat.h): the ACES filmic tone curve (Narkowicz 2015) on
// exposed linear radiance, then the sRGB OETF (IEC 61966-2-1). C++: include
// core/raster/display_shared.hpp (core/render/tone_map.hpp and core/raster/srgb.hpp use it).
// GLSL: `#define TS_GLSL 1`, then this file (the flythrough's shaders, gpu/fly/fly_frame.glsl).
// Single precision on both sides, as the 8-bit encoders have always computed it.
#ifndef TS_DISPLAY_SHARED_H
#define TS_DISPLAY_SHARED_H

#include "core/util/glsl_compat.h"

// Filmic curve of one exposed channel value, in [0, 1].
TS_INLINE float ts_filmic(float x) {
    x = max(x, 0.0f);
    float y = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
    return clamp(y, 0.0f, 1.0f);
}

// sRGB encoding of a linear value, clamped to [0, 1].
TS_INLINE float ts_srgb_oetf(float c) {
    c = clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * pow(c, 1.0f / 2.4f) - 0.055f;
}

#endif  // TS_DISPLAY_SHARED_H
