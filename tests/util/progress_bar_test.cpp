#include "core/util/progress_bar.hpp"

#include <gtest/gtest.h>
#include <thread>
#include <vector>

TEST(ProgressBar, QuietWhenStderrIsNotATerminal) {
    // ctest pipes stderr, so the default must be off: logs stay free of carriage returns.
    ts::ProgressBar bar("work", 10);
    EXPECT_FALSE(bar.enabled());
}

TEST(ProgressBar, DrawsRateAndEtaWhenEnabled) {
    ts::ProgressBar bar("work", 100, "px");
    bar.set_enabled(true);
    testing::internal::CaptureStderr();
    bar.advance(100);
    bar.finish();
    const std::string out = testing::internal::GetCapturedStderr();
    EXPECT_NE(out.find("100%"), std::string::npos) << out;
    EXPECT_NE(out.find("px/s"), std::string::npos) << out;
    EXPECT_NE(out.find("ETA"), std::string::npos) << out;
}

TEST(ProgressBar, AdvanceIsThreadSafe) {
    ts::ProgressBar bar("work", 4000);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&] { for (int i = 0; i < 1000; ++i) bar.advance(); });
    for (auto& th : threads) th.join();
    bar.finish();
    EXPECT_EQ(bar.done(), 4000u);
}
