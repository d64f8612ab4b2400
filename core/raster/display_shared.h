// The single definition of the display transform of every 8-bit picture, in the common subset
// of C++ and GLSL (core/util/glsl_compat.h): the ACES filmic tone curve (Narkowicz 2015) on the
// largest channel of exposed linear radiance, every channel scaled by the same gain (and, only
// beyond the curve's white, mixed towards white), then the sRGB OETF (IEC 61966-2-1). Scaling
// the channels alike keeps a pixel's chromaticity (a sunset sky stays orange); a curve per
// channel would pull every colour towards the primaries in the toe and towards white in the
// shoulder (docs/rendering.md, "Output and tone mapping").
// C++: include core/raster/display_shared.hpp (core/render/tone_map.hpp uses it). GLSL:
// `#define TS_GLSL 1`, then this file (the flythrough's shaders, gpu/fly/fly_frame.glsl).
// Single precision on both sides, as the 8-bit encoders have always computed it.
#ifndef TS_DISPLAY_SHARED_H
#define TS_DISPLAY_SHARED_H

#include "core/util/glsl_compat.h"

// The curve's gain filmic(m) / m at a pixel whose largest exposed channel is m, with
// filmic(x) = x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14) clamped to 1. Written without the
// division by m, so it holds at m = 0 (0.03 / 0.14); filmic reaches 1 at x = 7.24, so from 8 on
// the gain is 1 / m (and the products of huge m cannot overflow).
TS_INLINE float ts_filmic_gain(float m) {
    m = max(m, 0.0f);
    if (m >= 8.0f) return 1.0f / m;
    float g = (2.51f * m + 0.03f) / (m * (2.43f * m + 0.59f) + 0.14f);
    return m * g > 1.0f ? 1.0f / m : g;
}

// The gain of a pixel of exposed channels r, g, b (each 0 if negative): the share of the
// channel's light the display shows before whitening.
TS_INLINE float ts_display_gain(float r, float g, float b) { return ts_filmic_gain(max(max(r, g), b)); }

// The curve's white: filmic(x) = 1 at x = (0.56 + sqrt(0.56^2 + 4 0.08 0.14)) / 0.16.
#define TS_FILMIC_WHITE 7.2416563f

// Beyond the curve's white a pixel cannot get brighter on the display, only whiter, as film
// and eyes see the sun: its channels are mixed towards white by this share, 1 - white / m for a
// brightest channel m, so 0 up to the white and 1 for the sun's disc. Without it, a disc of
// reddened sunlight would show as its colour at full strength, darker than the sky around it.
TS_INLINE float ts_display_whitening(float r, float g, float b) {
    return max(1.0f - TS_FILMIC_WHITE / max(max(max(r, g), b), TS_FILMIC_WHITE), 0.0f);
}

// A channel's display-linear value, in [0, 1], from the channel c (not negative) and its
// pixel's gain and whitening.
TS_INLINE float ts_display_channel(float c, float gain, float whitening) {
    float v = min(c * gain, 1.0f);
    return v + (1.0f - v) * whitening;
}

// The curve itself, in [0, 1]: a grey pixel's display-linear value (x ts_filmic_gain(x) rounds
// differently by an ulp or so).
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

#ifdef TS_GLSL
// The display values (sRGB-encoded, in [0, 1]) of a pixel of exposed radiance. C++ spells the
// same steps with glm in core/render/tone_map.hpp (display_linear, srgb8_pixel).
vec3 ts_display(vec3 exposed) {
    vec3 x = max(exposed, vec3(0.0));
    float gain = ts_display_gain(x.r, x.g, x.b), whitening = ts_display_whitening(x.r, x.g, x.b);
    return vec3(ts_srgb_oetf(ts_display_channel(x.r, gain, whitening)),
                ts_srgb_oetf(ts_display_channel(x.g, gain, whitening)),
                ts_srgb_oetf(ts_display_channel(x.b, gain, whitening)));
}
#endif

#endif  // TS_DISPLAY_SHARED_H
