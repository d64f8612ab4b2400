#pragma once
// Linear radiance -> display: exposure (a fixed EV or automatic middle grey), a filmic curve
// that keeps each pixel's chromaticity, and the sRGB transfer function (OETF), then 8 bits.
// EXR output skips all of it (linear).
//
// Units: radiance as core/light/sky.hpp gives it (kcd/m^2, i.e. 1 = 1000 cd/m^2).
// Exposure value (EV100, ISO 100): the luminance that saturates the sensor is
//   L_sat = 1.2 * 2^EV cd/m^2   (ISO 2720 saturation-based speed; "sunny 16" ~ EV 15),
// so scale = 1000 / (1.2 * 2^EV) turns kcd/m^2 into sensor units where 1 = saturation.
// Auto exposure puts the log-average luminance at middle grey 0.18 (Reinhard et al. 2002).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "core/raster/display_shared.hpp"

namespace ts::render {

struct Exposure {
    bool automatic = true;
    double ev100 = 15.0;   // used when !automatic
    double key = 0.18;     // auto: where the log-average luminance lands
    // Dither the 8-bit codes (encode_rgb_dithered) against banding in smooth gradients (skies).
    bool dither = false;
};
// "auto" or a number (EV100, -10..30). Throws ts::InputError otherwise.
Exposure parse_exposure(std::string_view text);

// Rec. 709 luminance of linear RGB.
inline float luminance(const glm::vec3& c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

// exp(mean(log(L + delta))) over the finite pixels (NaN/inf skipped), delta = 1e-6 kcd/m^2 so
// black pixels do not send it to 0. Returns 0 if no pixel is finite. The sum of the logs is
// taken as the sum of the binary exponents plus the log of the product of the mantissas, one
// log per 512 pixels instead of one per pixel (a 500x500 frame: 1.7 ms -> 0.5 ms); it agrees
// with the sum of std::log to ~1e-14 relative (tests/render/tone_map_test.cpp).
double log_average_luminance(const glm::vec3* rgb, std::size_t count);

// The multiplier applied to linear radiance before the curve.
double exposure_scale(const Exposure& e, double log_average);

// ACES filmic curve fitted by Narkowicz (2015) of a grey value: x(2.51x+0.03) / (x(2.43x+0.59)+0.14),
// clamped to [0, 1]. Input 0.18 maps to ~0.27 (before the OETF).
float filmic(float x);

// The display-linear colour of exposed linear RGB, each channel in [0, 1]: the filmic curve on
// the largest channel m, every channel scaled by the same gain filmic(m) / m, so the colour keeps
// its chromaticity, up to the curve's white (m = 7.24); beyond it mixed towards white by
// 1 - 7.24 / m (core/raster/display_shared.h, shared with the flythrough's shaders).
// Negative channels count as 0, infinite ones as the largest float.
inline glm::vec3 display_linear(glm::vec3 exposed) {
    namespace s = raster::shared;
    constexpr float kLargest = 3.4028235e38f;
    for (int c = 0; c < 3; ++c) exposed[c] = std::min(std::max(exposed[c], 0.0f), kLargest);
    const float gain = s::ts_display_gain(exposed.x, exposed.y, exposed.z);
    const float whitening = s::ts_display_whitening(exposed.x, exposed.y, exposed.z);
    return {s::ts_display_channel(exposed.x, gain, whitening), s::ts_display_channel(exposed.y, gain, whitening),
            s::ts_display_channel(exposed.z, gain, whitening)};
}
// The 8-bit code of a display-linear value: lround(255 srgb_oetf(v)) (core/raster/srgb.hpp).
std::uint8_t srgb8_code(float display_linear);
// The codes of one pixel of exposed linear RGB (finite channels): srgb8_code of display_linear.
// Every encoder below equals it.
std::array<std::uint8_t, 3> srgb8_pixel(glm::vec3 exposed);

// srgb8_code without a pow per call. The code is monotone in v, so a table over [2^-14, 1) in
// steps of 1/512 octave (a step moves the code by at most ~0.4) holds the code at each step's
// start and the one v inside the step where the code goes up, found by bisection on
// srgb8_code itself. It equals srgb8_code except at isolated floats where srgb8_code's own
// float rounding steps back by one code (pow is not monotone to the last ulp right at a code
// boundary); there it gives the monotone neighbours' code (tests/render/tone_map_test.cpp).
// Building it costs ~3600 srgb8_code calls; a lookup is a few instructions, where srgb8_code
// costs a pow per channel.
class Srgb8Encoder {
public:
    Srgb8Encoder();
    // No table: every call evaluates srgb8_code (for a handful of pixels).
    enum Direct { direct };
    explicit Srgb8Encoder(Direct) {}
    // The code of a display-linear value.
    std::uint8_t operator()(float display_linear) const {
        if (!tabulated_) return srgb8_code(display_linear);
        if (!(display_linear >= kLow)) return 0;
        if (display_linear >= kHigh) return 255;
        std::uint32_t bits;
        std::memcpy(&bits, &display_linear, sizeof bits);
        const std::size_t i = (bits >> kShift) - kFirst;
        return std::uint8_t(code_[i] + (display_linear >= step_[i] ? 1 : 0));
    }
    // The codes of a pixel of exposed linear RGB (finite channels), as srgb8_pixel.
    std::array<std::uint8_t, 3> pixel(glm::vec3 exposed) const {
        const glm::vec3 v = display_linear(exposed);
        return {(*this)(v.x), (*this)(v.y), (*this)(v.z)};
    }
    // False if the OETF ever changed so that a step holds two code changes (or the ends are
    // not 0 and 255): then every call evaluates srgb8_code.
    bool tabulated() const { return tabulated_; }

    // out[3i .. 3i+2] = pixel(scale * rgb[i]) for count pixels; a pixel with a non-finite
    // channel becomes `nan_colour`. The same bytes as that loop, faster: the display-linear
    // values of a run of pixels are found first, then looked up in the table 8 at a time
    // (AVX2) through local pointers (a byte store may alias the vectors' own pointers, so a
    // loop over operator() reloads them after every byte it writes).
    void encode_rgb(const glm::vec3* rgb, std::size_t count, float scale, std::array<std::uint8_t, 3> nan_colour,
                    std::uint8_t* out) const;

    // The same with dither, for a picture `width` pixels wide: each channel's code is
    // floor(v + 0.5 + d) with v the exact code value 255 srgb_oetf(display_linear) before
    // rounding (interpolated in a table of v at the steps, to ~1e-3 of a code) and d in
    // [-0.5, 0.5) from interleaved gradient noise at the pixel (Jimenez 2014: frac(52.9829189
    // frac(0.06711056 i + 0.00583715 j))), a fixed pattern of the pixel position, so a picture is
    // reproducible and smooth gradients turn into fine grain instead of 8-bit bands. A code is
    // always one of the two nearest v, and their mean over the pattern is v.
    void encode_rgb_dithered(const glm::vec3* rgb, std::size_t count, int width, float scale,
                             std::array<std::uint8_t, 3> nan_colour, std::uint8_t* out) const;

private:
    // out[i] = (*this)(v[i]) for count display-linear values in [0, 1].
    void encode_values(const float* v, std::size_t count, std::uint8_t* out) const;
    std::size_t encode_values_avx2(const float* v, std::size_t count, std::uint8_t* out) const;

    static constexpr float kLow = 0x1p-14f, kHigh = 1.0f;
    static constexpr int kStepBits = 9;                 // steps per octave = 2^kStepBits
    static constexpr int kShift = 23 - kStepBits;
    static constexpr std::uint32_t kFirst = (127u - 14u) << kStepBits;
    static constexpr std::size_t kSteps = std::size_t(14) << kStepBits;
    bool tabulated_ = false;
    std::vector<std::uint8_t> code_;
    std::vector<float> step_;
    std::vector<float> value_;  // 255 srgb_oetf(v) at each step's start (kSteps + 1)
};

// A tabulated Srgb8Encoder built on first use and shared by every thread (it is read-only).
const Srgb8Encoder& shared_srgb8_table();

// rgb (linear, count pixels) -> 8-bit sRGB RGB interleaved. NaN pixels become `nan_colour`.
// With dither_width > 0: dithered (Srgb8Encoder::encode_rgb_dithered) for a picture that wide.
std::vector<std::uint8_t> tone_map_to_srgb8(const glm::vec3* rgb, std::size_t count, double scale,
                                            std::array<std::uint8_t, 3> nan_colour = {0, 0, 0},
                                            int dither_width = 0);

}  // namespace ts::render
