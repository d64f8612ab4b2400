#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include "core/render/tone_map.hpp"
#include "core/raster/srgb.hpp"
#include "core/util/error.hpp"

namespace ts::render {
namespace {

TEST(ToneMap, FilmicIsMonotoneAndBounded) {
    float prev = -1;
    for (float x = 0; x < 50; x += 0.01f) {
        const float y = filmic(x);
        EXPECT_GE(y, prev) << x;
        EXPECT_LE(y, 1.0f);
        prev = y;
    }
    EXPECT_FLOAT_EQ(filmic(0.0f), 0.0f);
    EXPECT_NEAR(filmic(0.18f), 0.2666f, 1e-3f);  // the Narkowicz fit at middle grey
    EXPECT_FLOAT_EQ(filmic(100.0f), 1.0f);
}

TEST(ToneMap, AutoExposurePutsLogAverageAtMiddleGrey) {
    std::vector<glm::vec3> px = {glm::vec3(2.0f), glm::vec3(8.0f)};
    const double avg = log_average_luminance(px.data(), px.size());
    EXPECT_NEAR(avg, 4.0, 1e-5);  // geometric mean of 2 and 8
    Exposure e;  // auto
    EXPECT_NEAR(exposure_scale(e, avg) * avg, 0.18, 1e-9);
}

// The log-average as it was computed before (one std::log per pixel), the reference for the
// exponent + mantissa-product form.
double log_average_by_logs(const std::vector<glm::vec3>& px) {
    double sum = 0;
    std::size_t n = 0;
    for (const auto& c : px) {
        const float l = luminance(c);
        if (!std::isfinite(l)) continue;
        sum += std::log(1e-6 + std::max(0.0f, l));
        ++n;
    }
    return n == 0 ? 0.0 : std::exp(sum / double(n));
}

TEST(ToneMap, LogAverageAgreesWithTheSumOfLogs) {
    std::mt19937 rng(5);
    int scale_changes = 0;
    for (int trial = 0; trial < 200; ++trial) {
        std::lognormal_distribution<float> radiance(float(trial % 7) - 3.0f, 0.5f + float(trial % 5));
        std::vector<glm::vec3> px(std::size_t(1 + trial * 997 % 70001));
        for (auto& c : px) c = glm::vec3(radiance(rng), radiance(rng), radiance(rng));
        px[0] = glm::vec3(0.0f);                        // black: delta keeps the log finite
        if (px.size() > 3) px[1] = glm::vec3(NAN);      // skipped
        if (px.size() > 3) px[2] = glm::vec3(-1.0f);    // clamped to 0
        if (px.size() > 9) px[7] = glm::vec3(3e38f);    // a huge finite pixel (a sun disc, and more)
        if (px.size() > 9) px[8] = glm::vec3(INFINITY); // skipped
        const double want = log_average_by_logs(px), got = log_average_luminance(px.data(), px.size());
        ASSERT_NEAR(got, want, 1e-13 * want) << trial;
        // What the pictures see: the float scale the tone map multiplies by.
        scale_changes += float(exposure_scale(Exposure{}, got)) != float(exposure_scale(Exposure{}, want));
    }
    EXPECT_EQ(scale_changes, 0);
    EXPECT_EQ(log_average_luminance(nullptr, 0), 0.0);
    const std::vector<glm::vec3> nan(5, glm::vec3(NAN));
    EXPECT_EQ(log_average_luminance(nan.data(), nan.size()), 0.0);
}

TEST(ToneMap, FixedEvFollowsSaturationSpeed) {
    const Exposure e = parse_exposure("15");
    EXPECT_FALSE(e.automatic);
    // 1.2 * 2^15 cd/m^2 = 39.3 kcd/m^2 saturates: its scale is 1/39.32.
    EXPECT_NEAR(exposure_scale(e, 0.0), 1000.0 / (1.2 * 32768.0), 1e-12);
    EXPECT_TRUE(parse_exposure("auto").automatic);
    EXPECT_THROW(parse_exposure("bright"), InputError);
    EXPECT_THROW(parse_exposure("99"), InputError);
}

TEST(ToneMap, EightBitOutputAndNan) {
    std::vector<glm::vec3> px = {glm::vec3(0.0f), glm::vec3(1000.0f), glm::vec3(NAN)};
    const auto b = tone_map_to_srgb8(px.data(), px.size(), 1.0, {1, 2, 3});
    ASSERT_EQ(b.size(), 9u);
    EXPECT_EQ(b[0], 0);
    EXPECT_EQ(b[3], 255);
    EXPECT_EQ(b[6], 1);
    EXPECT_EQ(b[8], 3);
}

// The table encoder must give srgb8_code's byte for every display-linear float, except where
// srgb8_code's own float evaluation is not monotone (an isolated float one code below or above
// its neighbours, at a code boundary): there it may differ by one, and only there. Checked at
// every step's ends, around every code change (all floats within +-32 ulps) and on a million
// log-uniform values.
TEST(ToneMap, TableEncoderEqualsTheCurveForEveryFloatTried) {
    const Srgb8Encoder enc;
    ASSERT_TRUE(enc.tabulated());
    auto bits_of = [](float f) {
        std::uint32_t b;
        std::memcpy(&b, &f, sizeof b);
        return b;
    };
    auto float_of = [](std::uint32_t b) {
        float f;
        std::memcpy(&f, &b, sizeof f);
        return f;
    };
    // Does the curve step back anywhere within +-256 ulps of x (x > 0)?
    auto curve_not_monotone_near = [&](float x) {
        const std::uint32_t b = bits_of(x);
        int prev = srgb8_code(float_of(b - 256));
        for (std::uint32_t c = b - 255; c <= b + 256; ++c) {
            const int code = srgb8_code(float_of(c));
            if (code < prev) return true;
            prev = code;
        }
        return false;
    };
    long checked = 0, blips = 0, mismatches = 0;
    auto check = [&](float x) {
        ++checked;
        const int table = enc(x), curve = srgb8_code(x);
        if (table == curve) return;
        if (x > 0 && std::abs(table - curve) == 1 && curve_not_monotone_near(x)) {
            ++blips;
            return;
        }
        if (++mismatches < 10) ADD_FAILURE() << "x = " << x << ": table " << table << ", curve " << curve;
    };
    // Every 1/512-octave step's first and last float over [2^-16, 2).
    for (std::uint32_t b = bits_of(0x1p-16f); b < bits_of(2.0f); b += 1u << 14) {
        check(float_of(b));
        check(float_of(b - 1));
    }
    // Around each code change, found by a scan in steps of 1/4096 octave.
    for (std::uint32_t b = bits_of(0x1p-15f); b < bits_of(1.0625f); b += 1u << 11)
        if (srgb8_code(float_of(b)) != srgb8_code(float_of(b + (1u << 11))))
            for (std::uint32_t c = b; c <= b + (1u << 11); c += 1u << 5)
                if (srgb8_code(float_of(c)) != srgb8_code(float_of(c + (1u << 5))))
                    for (std::uint32_t d = c; d <= c + (1u << 5); ++d) check(float_of(d));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> log2x(-20.0f, 1.0f);
    for (int i = 0; i < 1000000; ++i) check(std::exp2(log2x(rng)));
    for (float x : {-1.0f, -0.0f, 0.0f, 1e-30f, 0.99f, 1.0f, 2.0f, 100.0f, 1e15f}) check(x);
    EXPECT_EQ(enc(1e30f), 255);
    EXPECT_EQ(mismatches, 0) << "of " << checked;
    // The blips are rare: a few hundred floats among those around the ~255 code changes.
    EXPECT_LT(blips, checked / 1000) << "of " << checked;
    // And the table itself is monotone.
    std::uint8_t prev = 0;
    for (std::uint32_t b = bits_of(0x1p-15f); b < bits_of(1.125f); b += 13) {
        const std::uint8_t code = enc(float_of(b));
        ASSERT_GE(code, prev) << float_of(b);
        prev = code;
    }
}

TEST(ToneMap, LargeImagesUseTheTable) {
    std::vector<glm::vec3> px(20003);  // above the size where the table is built; not whole blocks of 8
    std::mt19937 rng(3);
    std::lognormal_distribution<float> radiance(0.0f, 1.5f);
    for (auto& c : px) c = glm::vec3(radiance(rng), radiance(rng), radiance(rng));
    px[17] = glm::vec3(NAN);
    // The table's edges and beyond: 0, negative, below 2^-14, the curve's clamp (7.24) and 8,
    // above, the largest floats.
    const float edges[] = {0.0f,  -0.0f,      -2.0f, 0x1p-15f, 0x1p-14f, 0x1.000002p-14f,
                           7.24f, 7.9999995f, 8.0f,  26.0f,    3e38f};
    for (std::size_t k = 0; k < std::size(edges); ++k)
        px[100 + k] = glm::vec3(edges[k], 0.5f * edges[k], -edges[k]);
    px[200] = glm::vec3(1.0f, INFINITY, 1.0f);
    px[201] = glm::vec3(-INFINITY, 1.0f, 1.0f);
    const Srgb8Encoder encoder;
    // 1e30: most products overflow to infinity (code 255).
    for (const double scale : {0.3, 1.0, 1e30}) {
        const auto b = tone_map_to_srgb8(px.data(), px.size(), scale, {9, 8, 7});
        for (std::size_t i = 0; i < px.size(); ++i)
            for (int k = 0; k < 3; ++k) {
                const bool nan_colour = i == 17 || i == 200 || i == 201;
                const std::uint8_t want =
                    nan_colour ? std::uint8_t(9 - k) : encoder.pixel(float(scale) * px[i])[std::size_t(k)];
                ASSERT_EQ(b[3 * i + std::size_t(k)], want) << scale << " " << i << " " << k;
            }
    }
}

// Dither: every code is one of the two nearest to the exact value 255 oetf(filmic(x)) of a grey, their
// mean over a flat patch is that value (so a smooth gradient keeps its average instead of
// stepping in bands), the pattern is fixed, and non-finite pixels still get the NaN colour.
TEST(ToneMap, DitherKeepsTheMeanAndStaysWithinOneCode) {
    const Srgb8Encoder& enc = shared_srgb8_table();
    ASSERT_TRUE(enc.tabulated());
    const int w = 64, h = 64;
    for (float x : {0.01f, 0.05f, 0.1234f, 0.18f, 0.5f, 1.7f}) {
        const std::vector<glm::vec3> px(std::size_t(w * h), glm::vec3(x));
        std::vector<std::uint8_t> out(px.size() * 3), again(px.size() * 3);
        enc.encode_rgb_dithered(px.data(), px.size(), w, 1.0f, {1, 2, 3}, out.data());
        enc.encode_rgb_dithered(px.data(), px.size(), w, 1.0f, {1, 2, 3}, again.data());
        EXPECT_EQ(out, again);
        const double exact = 255.0 * raster::srgb_oetf(filmic(x));
        double mean = 0;
        for (std::uint8_t c : out) {
            EXPECT_GE(c, std::floor(exact) - 1e-3) << x;
            EXPECT_LE(c, std::ceil(exact) + 1e-3) << x;
            mean += c;
        }
        mean /= double(out.size());
        EXPECT_NEAR(mean, exact, 0.03) << x;
    }
    std::vector<glm::vec3> px(16, glm::vec3(0.2f));
    px[5] = glm::vec3(NAN);
    std::vector<std::uint8_t> out(px.size() * 3);
    enc.encode_rgb_dithered(px.data(), px.size(), 4, 1.0f, {1, 2, 3}, out.data());
    EXPECT_EQ(out[15], 1);
    EXPECT_EQ(out[16], 2);
    EXPECT_EQ(out[17], 3);
}

// The curve keeps a colour's chromaticity: the 8-bit picture of random colours, decoded, has
// the CIE xy of the exposed radiance, up to the codes' rounding, wherever no channel saturates;
// and a pixel's brightest channel is the grey curve of it (so greys are as before).
TEST(ToneMap, AColourKeepsItsChromaticityThroughTheCurve) {
    auto xy = [](glm::dvec3 c) {
        const double X = 0.4124 * c.x + 0.3576 * c.y + 0.1805 * c.z;
        const double Y = 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
        const double Z = 0.0193 * c.x + 0.1192 * c.y + 0.9505 * c.z;
        return glm::dvec2(X, Y) / (X + Y + Z);
    };
    std::mt19937 rng(11);
    std::lognormal_distribution<float> radiance(-1.0f, 1.2f);
    std::uniform_real_distribution<float> tint(0.25f, 1.0f);
    std::vector<glm::vec3> px(40000);
    for (auto& c : px) c = radiance(rng) * glm::vec3(tint(rng), tint(rng), tint(rng));
    const auto b = tone_map_to_srgb8(px.data(), px.size(), 1.0);
    double worst = 0;
    int compared = 0;
    for (std::size_t i = 0; i < px.size(); ++i) {
        const std::uint8_t* code = &b[3 * i];
        const int lo = std::min({code[0], code[1], code[2]}), hi = std::max({code[0], code[1], code[2]});
        const float m = std::max({px[i].x, px[i].y, px[i].z});
        EXPECT_NEAR(hi, 255.0 * raster::srgb_oetf(filmic(m)), 0.5 + 1e-3) << i;
        // Codes below 64 round by over 1.5% of their light: their xy is the rounding's.
        if (lo < 64 || hi == 255) continue;
        glm::dvec3 shown;
        for (int k = 0; k < 3; ++k) shown[k] = raster::srgb_eotf(float(code[k]) / 255.0f);
        worst = std::max(worst, glm::length(xy(shown) - xy(glm::dvec3(px[i]))));
        ++compared;
    }
    EXPECT_GT(compared, 10000);
    EXPECT_LT(worst, 0.004) << "of " << compared;
}

}  // namespace
}  // namespace ts::render
