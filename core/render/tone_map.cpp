#include "core/render/tone_map.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include <glm/vec3.hpp>

#include "core/util/error.hpp"

namespace ts::render {

Exposure parse_exposure(std::string_view text) {
    Exposure e;
    if (text == "auto") return e;
    double ev = 0;
    const auto* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, ev);
    if (ec != std::errc() || ptr != end || !std::isfinite(ev) || ev < -10 || ev > 30)
        throw InputError("--exposure " + std::string(text) + ": give auto or an EV100 number in -10..30");
    e.automatic = false;
    e.ev100 = ev;
    return e;
}

double log_average_luminance(const glm::vec3* rgb, std::size_t count) {
    constexpr double kDelta = 1e-6;
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const float l = luminance(rgb[i]);
        if (!std::isfinite(l)) continue;
        sum += std::log(kDelta + std::max(0.0f, l));
        ++n;
    }
    return n == 0 ? 0.0 : std::exp(sum / double(n));
}

double exposure_scale(const Exposure& e, double log_average) {
    if (!e.automatic) return 1000.0 / (1.2 * std::exp2(e.ev100));
    return log_average > 0 ? e.key / log_average : 1.0;
}

float filmic(float x) {
    x = std::max(0.0f, x);
    const float y = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
    return std::clamp(y, 0.0f, 1.0f);
}

float srgb_oetf(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

float srgb_eotf(float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

std::vector<std::uint8_t> tone_map_to_srgb8(const glm::vec3* rgb, std::size_t count, double scale,
                                            std::array<std::uint8_t, 3> nan_colour) {
    // The curve is smooth and the output has 256 levels: a table over the exposed value in
    // log steps would do, but 3 pow() per pixel on <= a few Mpx costs milliseconds.
    std::vector<std::uint8_t> out(count * 3);
    const float s = float(scale);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::vec3 c = rgb[i];
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
            out[3 * i] = nan_colour[0], out[3 * i + 1] = nan_colour[1], out[3 * i + 2] = nan_colour[2];
            continue;
        }
        for (int k = 0; k < 3; ++k)
            out[3 * i + std::size_t(k)] = std::uint8_t(std::lround(255.0f * srgb_oetf(filmic(s * c[k]))));
    }
    return out;
}

}  // namespace ts::render
