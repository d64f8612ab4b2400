#include "core/render/tone_map.hpp"

#include <immintrin.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>

#include <glm/vec3.hpp>

#include "core/raster/display_shared.hpp"
#include "core/raster/srgb.hpp"
#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::render {

Exposure parse_exposure(std::string_view text) {
    Exposure e;
    if (text == "auto") return e;
    double ev = 0;
    const auto* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, ev);
    if (ec != std::errc() || ptr != end || !std::isfinite(ev) || ev < -10 || ev > 30)
        throw QuantityError(Quantity::exposure, std::string(text), "give auto or an EV100 number in -10..30");
    e.automatic = false;
    e.ev100 = ev;
    return e;
}

double log_average_luminance(const glm::vec3* rgb, std::size_t count) {
    constexpr double kDelta = 1e-6;
    // x = 2^e m with m in [1, 2): sum log x = ln 2 * sum e + log(prod m). A product of 512
    // mantissas stays below 2^512, far from overflow, before its log is taken.
    constexpr std::size_t kBlock = 512;
    constexpr std::uint64_t kMantissa = (std::uint64_t(1) << 52) - 1, kOne = std::uint64_t(1023) << 52;
    std::int64_t exponents = 0;
    double log_mantissas = 0;
    std::size_t n = 0;
    for (std::size_t begin = 0; begin < count; begin += kBlock) {
        const std::size_t end = std::min(count, begin + kBlock);
        double product = 1;
        for (std::size_t i = begin; i < end; ++i) {
            const float l = luminance(rgb[i]);
            if (!std::isfinite(l)) continue;
            const double x = kDelta + std::max(0.0f, l);  // normal, positive: 1e-6 <= x < 2^128
            std::uint64_t bits;
            std::memcpy(&bits, &x, sizeof bits);
            exponents += std::int64_t(bits >> 52) - 1023;
            bits = (bits & kMantissa) | kOne;
            double m;
            std::memcpy(&m, &bits, sizeof m);
            product *= m;
            ++n;
        }
        log_mantissas += std::log(product);
    }
    if (n == 0) return 0.0;
    return std::exp((double(exponents) * std::numbers::ln2 + log_mantissas) / double(n));
}

double exposure_scale(const Exposure& e, double log_average) {
    if (!e.automatic) return 1000.0 / (1.2 * std::exp2(e.ev100));
    return log_average > 0 ? e.key / log_average : 1.0;
}

float filmic(float x) { return raster::shared::ts_filmic(x); }

std::uint8_t srgb8_code(float display_linear) {
    return std::uint8_t(std::lround(255.0f * raster::srgb_oetf(display_linear)));
}

std::array<std::uint8_t, 3> srgb8_pixel(glm::vec3 exposed) {
    const glm::vec3 v = display_linear(exposed);
    return {srgb8_code(v.x), srgb8_code(v.y), srgb8_code(v.z)};
}

namespace {
float float_of(std::uint32_t bits) {
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}
std::uint32_t bits_of(float f) {
    std::uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
}
bool finite(const glm::vec3& c) { return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z); }
}  // namespace

Srgb8Encoder::Srgb8Encoder() {
    // Positive floats order like their bit patterns: bisect on the bits for the smallest v with
    // code >= k, k = 1..255.
    if (srgb8_code(std::nextafter(kLow, 0.0f)) != 0 || srgb8_code(kHigh) != 255) return;
    std::vector<float> up(256);  // up[k]: smallest v with code >= k
    for (int k = 1; k <= 255; ++k) {
        std::uint32_t lo = bits_of(kLow) - 1, hi = bits_of(kHigh);  // code(lo) < k <= code(hi)
        while (hi - lo > 1) {
            const std::uint32_t mid = lo + (hi - lo) / 2;
            (srgb8_code(float_of(mid)) >= k ? hi : lo) = mid;
        }
        up[std::size_t(k)] = float_of(hi);
    }
    code_.resize(kSteps + 3);  // + 3: the AVX2 path reads 4 bytes per code
    step_.resize(kSteps);
    int k = 1;  // next code change not yet passed
    for (std::size_t i = 0; i < kSteps; ++i) {
        const float start = float_of(std::uint32_t((kFirst + i) << kShift));
        const float end = float_of(std::uint32_t((kFirst + i + 1) << kShift));
        while (k <= 255 && up[std::size_t(k)] <= start) ++k;
        code_[i] = std::uint8_t(k - 1);
        step_[i] = std::numeric_limits<float>::infinity();
        if (k <= 255 && up[std::size_t(k)] < end) {
            step_[i] = up[std::size_t(k)];
            if (k + 1 <= 255 && up[std::size_t(k + 1)] < end) return;  // two changes in one step
        }
    }
    value_.resize(kSteps + 1);
    for (std::size_t i = 0; i <= kSteps; ++i)
        value_[i] = 255.0f * raster::srgb_oetf(float_of(std::uint32_t((kFirst + i) << kShift)));
    tabulated_ = true;
}

// The table lookup for 8 values at a time: each is clamped into the table, its step found from
// the float's bits, code and step gathered, and the ends selected by masks; the same bytes as
// operator(). Returns the values done (a multiple of 8).
__attribute__((target("avx2"))) std::size_t Srgb8Encoder::encode_values_avx2(const float* v, std::size_t count,
                                                                            std::uint8_t* out) const {
    const __m256 vlow = _mm256_set1_ps(kLow), vhigh = _mm256_set1_ps(kHigh);
    const __m256 vbelow_high = _mm256_set1_ps(0x1.fffffep-1f);  // the float before kHigh = 1
    const __m256i vfirst = _mm256_set1_epi32(int(kFirst)), v255 = _mm256_set1_epi32(255);
    // Byte 0 of each 32-bit lane to the front of its 128-bit half, then the two halves' words
    // together: 8 codes as 8 bytes.
    const __m256i pick = _mm256_setr_epi8(0, 4, 8, 12, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,  //
                                          0, 4, 8, 12, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1);
    const __m256i join = _mm256_setr_epi32(0, 4, 1, 1, 1, 1, 1, 1);
    const int* code = reinterpret_cast<const int*>(code_.data());  // 4 bytes read per code: padded
    const float* step = step_.data();
    std::size_t done = 0;
    for (; done + 8 <= count; done += 8) {
        const __m256 x = _mm256_loadu_ps(v + done);
        const __m256 t = _mm256_min_ps(_mm256_max_ps(x, vlow), vbelow_high);
        const __m256i index = _mm256_sub_epi32(_mm256_srli_epi32(_mm256_castps_si256(t), kShift), vfirst);
        const __m256 threshold = _mm256_i32gather_ps(step, index, 4);
        __m256i c = _mm256_and_si256(_mm256_i32gather_epi32(code, index, 1), v255);
        c = _mm256_sub_epi32(c, _mm256_castps_si256(_mm256_cmp_ps(t, threshold, _CMP_GE_OQ)));  // +1
        c = _mm256_and_si256(c, _mm256_castps_si256(_mm256_cmp_ps(x, vlow, _CMP_GE_OQ)));
        c = _mm256_or_si256(c, _mm256_and_si256(_mm256_castps_si256(_mm256_cmp_ps(x, vhigh, _CMP_GE_OQ)), v255));
        const __m256i bytes = _mm256_permutevar8x32_epi32(_mm256_shuffle_epi8(c, pick), join);
        _mm_storel_epi64(reinterpret_cast<__m128i*>(out + done), _mm256_castsi256_si128(bytes));
    }
    return done;
}

void Srgb8Encoder::encode_values(const float* v, std::size_t count, std::uint8_t* out) const {
    if (!tabulated_) {
        for (std::size_t i = 0; i < count; ++i) out[i] = srgb8_code(v[i]);
        return;
    }
    std::size_t i = __builtin_cpu_supports("avx2") ? encode_values_avx2(v, count, out) : 0;
    const std::uint8_t* const code = code_.data();
    const float* const step = step_.data();
    for (; i < count; ++i) {
        const float x = v[i];
        std::uint8_t c = 0;
        if (x >= kHigh) {
            c = 255;
        } else if (x >= kLow) {
            std::uint32_t bits;
            std::memcpy(&bits, &x, sizeof bits);
            const std::size_t s = (bits >> kShift) - kFirst;
            c = std::uint8_t(code[s] + (x >= step[s] ? 1 : 0));
        }
        out[i] = c;
    }
}

namespace {

// display_linear of scale * rgb[i] for 8 pixels at a time into v (3 floats per pixel): the
// same operations in the same order as the scalar text, so the same floats. Each block's 24
// channels are scaled, clamped and stored; the pixels' largest channels gathered back from the
// store; the gain and the whitening found for 8 pixels at once and spread over their channels
// by permutes. Non-finite inputs give finite values (the caller overwrites those pixels) and set
// *any_not_finite. Returns the pixels done (a multiple of 8).
__attribute__((target("avx2"))) std::size_t display_values_avx2(const glm::vec3* rgb, std::size_t count, float scale,
                                                               float* v, bool* any_not_finite) {
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float));
    const float* in = &rgb[0].x;
    const __m256 vscale = _mm256_set1_ps(scale), zero = _mm256_setzero_ps(), one = _mm256_set1_ps(1.0f);
    const __m256 largest = _mm256_set1_ps(3.4028235e38f), eight = _mm256_set1_ps(8.0f);
    const __m256 white = _mm256_set1_ps(TS_FILMIC_WHITE);
    const __m256 k251 = _mm256_set1_ps(2.51f), k003 = _mm256_set1_ps(0.03f), k243 = _mm256_set1_ps(2.43f),
                 k059 = _mm256_set1_ps(0.59f), k014 = _mm256_set1_ps(0.14f);
    const __m256i stride = _mm256_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21);
    const __m256i spread[3] = {_mm256_setr_epi32(0, 0, 0, 1, 1, 1, 2, 2), _mm256_setr_epi32(2, 3, 3, 3, 4, 4, 4, 5),
                               _mm256_setr_epi32(5, 5, 6, 6, 6, 7, 7, 7)};
    const __m256i exponent = _mm256_set1_epi32(0x7f800000);
    __m256i finite = _mm256_set1_epi32(-1);
    std::size_t done = 0;
    for (; done + 8 <= count; done += 8, in += 24, v += 24) {
        __m256 x[3];
        for (int k = 0; k < 3; ++k) {
            const __m256 raw = _mm256_loadu_ps(in + 8 * k);
            const __m256i e = _mm256_and_si256(_mm256_castps_si256(raw), exponent);
            finite = _mm256_andnot_si256(_mm256_cmpeq_epi32(e, exponent), finite);
            x[k] = _mm256_min_ps(_mm256_max_ps(_mm256_mul_ps(raw, vscale), zero), largest);
            _mm256_storeu_ps(v + 8 * k, x[k]);
        }
        const __m256 red = _mm256_i32gather_ps(v, stride, 4), green = _mm256_i32gather_ps(v + 1, stride, 4);
        const __m256 m = _mm256_max_ps(_mm256_max_ps(red, green), _mm256_i32gather_ps(v + 2, stride, 4));
        // ts_filmic_gain and ts_display_whitening (core/raster/display_shared.h).
        const __m256 num = _mm256_add_ps(_mm256_mul_ps(k251, m), k003);
        const __m256 den = _mm256_add_ps(_mm256_mul_ps(m, _mm256_add_ps(_mm256_mul_ps(k243, m), k059)), k014);
        const __m256 curve = _mm256_div_ps(num, den), inverse = _mm256_div_ps(one, m);
        const __m256 use_inverse = _mm256_or_ps(_mm256_cmp_ps(m, eight, _CMP_GE_OQ),
                                                _mm256_cmp_ps(_mm256_mul_ps(m, curve), one, _CMP_GT_OQ));
        const __m256 gain = _mm256_blendv_ps(curve, inverse, use_inverse);
        const __m256 whitening =
            _mm256_max_ps(_mm256_sub_ps(one, _mm256_div_ps(white, _mm256_max_ps(m, white))), zero);
        for (int k = 0; k < 3; ++k) {
            const __m256 g = _mm256_permutevar8x32_ps(gain, spread[k]);
            const __m256 w = _mm256_permutevar8x32_ps(whitening, spread[k]);
            const __m256 c = _mm256_min_ps(_mm256_mul_ps(x[k], g), one);
            _mm256_storeu_ps(v + 8 * k, _mm256_add_ps(c, _mm256_mul_ps(_mm256_sub_ps(one, c), w)));
        }
    }
    if (!_mm256_testc_si256(finite, _mm256_set1_epi32(-1))) *any_not_finite = true;
    return done;
}

}  // namespace

void Srgb8Encoder::encode_rgb(const glm::vec3* rgb, std::size_t count, float scale,
                              std::array<std::uint8_t, 3> nan_colour, std::uint8_t* out) const {
    // Runs of pixels small enough for their display-linear values to stay in the L1 cache.
    constexpr std::size_t kRun = 512;
    float v[3 * kRun];
    const bool avx2 = __builtin_cpu_supports("avx2");
    for (std::size_t begin = 0; begin < count; begin += kRun) {
        const std::size_t n = std::min(kRun, count - begin);
        bool any_not_finite = false;
        std::size_t i = avx2 ? display_values_avx2(rgb + begin, n, scale, v, &any_not_finite) : 0;
        for (; i < n; ++i) {
            const glm::vec3 c = rgb[begin + i];
            glm::vec3 d(0.0f);
            if (finite(c))
                d = display_linear(scale * c);
            else
                any_not_finite = true;
            v[3 * i] = d.x, v[3 * i + 1] = d.y, v[3 * i + 2] = d.z;
        }
        std::uint8_t* o = out + 3 * begin;
        encode_values(v, 3 * n, o);
        if (!any_not_finite) continue;
        for (std::size_t j = 0; j < n; ++j)
            if (!finite(rgb[begin + j]))
                o[3 * j] = nan_colour[0], o[3 * j + 1] = nan_colour[1], o[3 * j + 2] = nan_colour[2];
    }
}

void Srgb8Encoder::encode_rgb_dithered(const glm::vec3* rgb, std::size_t count, int width, float scale,
                                       std::array<std::uint8_t, 3> nan_colour, std::uint8_t* out) const {
    if (!tabulated_ || width <= 0) {
        encode_rgb(rgb, count, scale, nan_colour, out);
        return;
    }
    constexpr std::uint32_t kStepMask = (1u << kShift) - 1;
    const float* value = value_.data();
    auto code_value = [value](float x) -> float {  // 255 srgb_oetf(x), interpolated
        if (!(x >= kLow)) return 0.0f;
        if (x >= kHigh) return 255.0f;
        std::uint32_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        const std::size_t i = (bits >> kShift) - kFirst;
        const float t = float(bits & kStepMask) * (1.0f / float(kStepMask + 1));
        return value[i] + (value[i + 1] - value[i]) * t;
    };
    for (std::size_t k = 0; k < count; ++k, out += 3) {
        const glm::vec3 c = rgb[k];
        if (!finite(c)) {
            out[0] = nan_colour[0], out[1] = nan_colour[1], out[2] = nan_colour[2];
            continue;
        }
        const glm::vec3 d = display_linear(scale * c);
        const float px = float(k % std::size_t(width)), py = float(k / std::size_t(width));
        const float f = 0.06711056f * px + 0.00583715f * py;
        const float g = 52.9829189f * (f - std::floor(f));
        const float noise = (g - std::floor(g)) - 0.5f;
        for (int ch = 0; ch < 3; ++ch) {
            const float v = code_value(d[ch]) + 0.5f + noise;
            out[ch] = std::uint8_t(std::clamp(std::floor(v), 0.0f, 255.0f));
        }
    }
}

const Srgb8Encoder& shared_srgb8_table() {
    static const Srgb8Encoder table;
    return table;
}

std::vector<std::uint8_t> tone_map_to_srgb8(const glm::vec3* rgb, std::size_t count, double scale,
                                            std::array<std::uint8_t, 3> nan_colour, int dither_width) {
    std::vector<std::uint8_t> out(count * 3);
    // The table is built once per process (a frame sequence would rebuild it per frame), and
    // not at all for small pictures, where building it would cost more than it saves.
    static const Srgb8Encoder direct(Srgb8Encoder::direct);
    const Srgb8Encoder& encoder = count >= 16384 ? shared_srgb8_table() : direct;
    if (dither_width > 0)
        shared_srgb8_table().encode_rgb_dithered(rgb, count, dither_width, float(scale), nan_colour, out.data());
    else
        encoder.encode_rgb(rgb, count, float(scale), nan_colour, out.data());
    return out;
}

}  // namespace ts::render
