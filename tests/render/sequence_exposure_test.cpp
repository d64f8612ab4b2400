// The time-lapse exposure: bounded against the brightest frame, a centred average over frames.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/render/sequence_exposure.hpp"
#include "core/render/tone_map.hpp"

namespace ts::render {
namespace {

TEST(SequenceExposure, EvOfScaleInvertsTheToneMapsScale) {
    for (double ev : {-2.0, 0.0, 9.5, 15.0}) {
        Exposure e;
        e.automatic = false;
        e.ev100 = ev;
        EXPECT_NEAR(ev100_of_scale(exposure_scale(e, 0.0)), ev, 1e-12);
    }
}

TEST(SequenceExposure, ACentredAverageDecidedKFramesLater) {
    SequenceExposure s(15.0, {3.0, 1, 900.0});
    s.add(14.0, 0);
    EXPECT_EQ(s.decided(), 0u);  // frame 0 waits for frame 1
    s.add(13.0, 60);
    EXPECT_EQ(s.decided(), 1u);
    const double w = std::exp(-0.5 * (60.0 / 900.0) * (60.0 / 900.0));  // a minute apart: nearly 1
    EXPECT_NEAR(s.ev(0), (14.0 + w * 13.0) / (1 + w), 1e-12);  // the window truncated at the start
    s.add(13.0, 120);
    EXPECT_NEAR(s.ev(1), (w * 14.0 + 13.0 + w * 13.0) / (1 + 2 * w), 1e-12);
    s.finish();
    EXPECT_EQ(s.decided(), 3u);
    EXPECT_NEAR(s.ev(2), 13.0, 1e-12);
}

TEST(SequenceExposure, FramesFarApartInTimeKeepTheirOwn) {
    // Two hours apart, dawn does not take noon's exposure.
    SequenceExposure s(15.0, {3.0, 2, 900.0});
    for (int k = 0; k < 5; ++k) s.add(12.0 + k, 7200.0 * k);
    s.finish();
    for (int k = 0; k < 5; ++k) EXPECT_NEAR(s.ev(std::size_t(k)), 12.0 + k, 1e-6) << k;
}

TEST(SequenceExposure, NeverMoreThanTheBoostBelowTheReference) {
    SequenceExposure s(15.0, {3.0, 0, 900.0});  // no window: each frame its own target
    double t = 0;
    for (double own : {2.0, 13.0, 16.0, std::numeric_limits<double>::infinity(), std::nan("")}) s.add(own, t += 60);
    s.finish();
    EXPECT_DOUBLE_EQ(s.ev(0), 12.0);  // a near-black night frame is not pushed to middle grey
    EXPECT_DOUBLE_EQ(s.ev(1), 13.0);
    EXPECT_DOUBLE_EQ(s.ev(2), 16.0);  // brighter than the reference: its own exposure
    EXPECT_DOUBLE_EQ(s.ev(3), 12.0);  // an all-black frame
    EXPECT_DOUBLE_EQ(s.ev(4), 12.0);
}

TEST(SequenceExposure, AMorningAndAnEveningAtTheSameSunGetTheSameExposure) {
    // A day's own EVs rise to noon and fall again, symmetric in time: the exposures are too (a
    // running average lagged behind and made the morning brighter than the evening).
    std::vector<double> own;
    for (int k = 0; k <= 12; ++k) own.push_back(15.0 - 0.08 * (k - 6) * (k - 6));
    SequenceExposure s(15.0);
    for (std::size_t k = 0; k < own.size(); ++k) s.add(own[k], 600.0 * double(k));
    s.finish();
    for (std::size_t k = 0; k < own.size(); ++k) EXPECT_NEAR(s.ev(k), s.ev(own.size() - 1 - k), 1e-12) << k;
}

}  // namespace
}  // namespace ts::render
