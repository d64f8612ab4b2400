#pragma once
// Linear radiance -> display: exposure (a fixed EV or automatic middle grey), a filmic curve,
// and the sRGB transfer function (OETF), then 8 bits. EXR output skips all of it (linear).
//
// Units: radiance as core/light/sky.hpp gives it (kcd/m^2, i.e. 1 = 1000 cd/m^2).
// Exposure value (EV100, ISO 100): the luminance that saturates the sensor is
//   L_sat = 1.2 * 2^EV cd/m^2   (ISO 2720 saturation-based speed; "sunny 16" ~ EV 15),
// so scale = 1000 / (1.2 * 2^EV) turns kcd/m^2 into sensor units where 1 = saturation.
// Auto exposure puts the log-average luminance at middle grey 0.18 (Reinhard et al. 2002).
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace ts::render {

struct Exposure {
    bool automatic = true;
    double ev100 = 15.0;   // used when !automatic
    double key = 0.18;     // auto: where the log-average luminance lands
};
// "auto" or a number (EV100, -10..30). Throws ts::InputError otherwise.
Exposure parse_exposure(std::string_view text);

// Rec. 709 luminance of linear RGB.
inline float luminance(const glm::vec3& c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

// exp(mean(log(L + delta))) over the finite pixels (NaN/inf skipped), delta = 1e-6 kcd/m^2 so
// black pixels do not send it to 0. Returns 0 if no pixel is finite.
double log_average_luminance(const glm::vec3* rgb, std::size_t count);

// The multiplier applied to linear radiance before the curve.
double exposure_scale(const Exposure& e, double log_average);

// ACES filmic curve fitted by Narkowicz (2015): x(2.51x+0.03) / (x(2.43x+0.59)+0.14), clamped
// to [0, 1]; per channel. Input 0.18 maps to ~0.27 (before the OETF).
float filmic(float x);
// sRGB OETF (IEC 61966-2-1): linear [0, 1] -> encoded [0, 1].
float srgb_oetf(float linear);
// Its inverse (8-bit orthophotos -> linear albedo).
float srgb_eotf(float encoded);

// rgb (linear, count pixels) -> 8-bit sRGB RGB interleaved. NaN pixels become `nan_colour`.
std::vector<std::uint8_t> tone_map_to_srgb8(const glm::vec3* rgb, std::size_t count, double scale,
                                            std::array<std::uint8_t, 3> nan_colour = {0, 0, 0});

}  // namespace ts::render
