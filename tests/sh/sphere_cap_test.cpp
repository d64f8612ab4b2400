// ts_sphere_cap_rd (sh_shared.h) in single precision, as the CPU kernel and the GPU run it,
// against the half-angle in long double: the inverse distance, cosine, sine and 1 - cos of the
// cap, near grazing and for caps too small for 1 - cos computed as a difference.
#include <gtest/gtest.h>

#include <cmath>

#include "core/sh/sh_shared_float.hpp"

namespace {

struct Case {
    float r, d;
};

TEST(SphereCap, FromRadiusAndDistanceInFloatMatchesTheHalfAngle) {
    const Case cases[] = {{1.0f, 2.0f},          {1.0f, 1.0001f},  {1.0f, 1.0f + 1e-6f}, {0.001f, 1.0f},
                          {1e-4f, 10.0f},        {3.0f, 1000.0f},  {50.0f, 51.0f},       {0.25f, 7.5f},
                          {1.0f, 1e6f},          {400.0f, 401.0f}};
    for (const Case& c : cases) {
        float cap[4];
        ts::sh::shared_float::ts_sphere_cap_rd(c.r, c.d, cap);
        const long double r = c.r, d = c.d;
        const long double sb = r / d, cb = std::sqrt((d - r) * (d + r)) / d;
        const long double omc = sb * sb / (1.0L + cb);
        const long double want[4] = {1.0L / d, cb, sb, omc};
        for (int i = 0; i < 4; ++i) {
            const long double err = std::fabs(cap[i] - want[i]) / std::fabs(want[i]);
            EXPECT_LT(err, 4e-7L) << "r " << c.r << " d " << c.d << " entry " << i;
        }
    }
}

TEST(SphereCap, InsideOrOnTheSphereIsTheWholeSphere) {
    for (const Case& c : {Case{1.0f, 1.0f}, Case{2.0f, 0.5f}, Case{1.0f, 0.0f}}) {
        float cap[4];
        ts::sh::shared_float::ts_sphere_cap_rd(c.r, c.d, cap);
        EXPECT_EQ(cap[0], 0.0f);
        EXPECT_EQ(cap[1], -1.0f);
        EXPECT_EQ(cap[2], 0.0f);
        EXPECT_EQ(cap[3], 2.0f);
    }
}

}  // namespace
