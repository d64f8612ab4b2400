#include "core/raster/srgb.hpp"

#include <gtest/gtest.h>

namespace ts::raster {
namespace {

TEST(Srgb, OetfKnownValues) {
    // IEC 61966-2-1: linear 0.0031308 is the knee; 0.5 encodes to 0.7354; the pair inverts.
    EXPECT_FLOAT_EQ(srgb_oetf(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(srgb_oetf(1.0f), 1.0f);
    EXPECT_NEAR(srgb_oetf(0.5f), 0.735357f, 1e-5f);
    EXPECT_NEAR(srgb_oetf(0.002f), 0.02584f, 1e-5f);
    for (float v : {0.001f, 0.01f, 0.2f, 0.7f, 0.99f}) EXPECT_NEAR(srgb_eotf(srgb_oetf(v)), v, 1e-6f);
}

}  // namespace
}  // namespace ts::raster
