#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/render/tone_map.hpp"
#include "core/util/error.hpp"

namespace ts::render {
namespace {

TEST(ToneMap, SrgbOetfKnownValues) {
    // IEC 61966-2-1: linear 0.0031308 is the knee; 0.5 encodes to 0.7354; the pair inverts.
    EXPECT_FLOAT_EQ(srgb_oetf(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(srgb_oetf(1.0f), 1.0f);
    EXPECT_NEAR(srgb_oetf(0.5f), 0.735357f, 1e-5f);
    EXPECT_NEAR(srgb_oetf(0.002f), 0.02584f, 1e-5f);
    for (float v : {0.001f, 0.01f, 0.2f, 0.7f, 0.99f}) EXPECT_NEAR(srgb_eotf(srgb_oetf(v)), v, 1e-6f);
}

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

}  // namespace
}  // namespace ts::render
