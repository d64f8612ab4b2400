// The time-lapse exposure: bounded against the brightest frame, smoothed from frame to frame.
#include <cmath>
#include <limits>

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

TEST(SequenceExposure, FirstFrameIsItsOwnThenAMovingAverage) {
    SequenceExposure s(15.0, {3.0, 0.5});
    EXPECT_DOUBLE_EQ(s.next(14.0), 14.0);
    EXPECT_DOUBLE_EQ(s.next(13.0), 13.5);
    EXPECT_DOUBLE_EQ(s.next(13.0), 13.25);
}

TEST(SequenceExposure, NeverMoreThanTheBoostBelowTheReference) {
    SequenceExposure s(15.0, {3.0, 1.0});  // smoothing 1: each frame its own target
    EXPECT_DOUBLE_EQ(s.next(2.0), 12.0);   // a near-black night frame is not pushed to middle grey
    EXPECT_DOUBLE_EQ(s.next(13.0), 13.0);
    EXPECT_DOUBLE_EQ(s.next(16.0), 16.0);  // brighter than the reference: its own exposure
    EXPECT_DOUBLE_EQ(s.next(std::numeric_limits<double>::infinity()), 12.0);  // an all-black frame
    EXPECT_DOUBLE_EQ(s.next(std::nan("")), 12.0);
}

}  // namespace
}  // namespace ts::render
