// `terrashade render --device vulkan` against `render --device cpu`: the same
// picture within the GPU backend's tolerances (tests/gpu/render_backend_test.cpp states them
// stage by stage), which path ran said on stdout, and the fallbacks and errors of --device.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/cli/cli_support.hpp"
#include "tests/cli/frame_pixels.hpp"

namespace fs = std::filesystem;

namespace {

// 101 x 101 texels around Grenoble (as render_cli_test.cpp): the city, the Isere, two massifs.
const std::string kRender = "render " + ts::cli_test::kDem + ts::cli_test::kCrop + " --sun-azimuth 135 --sun-elevation 25";

// Tolerance between the two pictures (linear EXR, per channel, relative to the CPU value).
// The GPU backend keeps T in fp32; the default CPU path streams T in fp16 (its stated 1e-3 of
// the radiance) and the two transfers differ by 1e-4 of T: every channel within kMaxRel.
// A horizon "flip" (tests/gpu/render_backend_test.cpp: at most 1e-4 of the texel-azimuths)
// moves that texel's sky light by more: at most kFlipFraction of the channels may exceed it.
constexpr double kMaxRel = 2e-3;
constexpr double kFlipFraction = 1e-3;

using ts::cli_test::Result;
using ts::cli_test::run_ts;
using ts::cli_test::kNoVulkan;

// The first three channels as floats (0..1 for an 8-bit picture).
std::vector<float> read_rgb_float(const fs::path& path, int& width) {
    ts::raster::FloatImage f = ts::cli_test::read_float_rgb(path);
    width = f.width;
    return std::move(f.rgb);
}

class RenderGpuCli : public ::testing::Test {
protected:
    fs::path dir_ = ts::cli_test::temp_root() / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    void SetUp() override { fs::create_directories(dir_); }
};

}  // namespace

TEST_F(RenderGpuCli, VulkanGivesTheCpuPicture) {
    for (const std::string method : {"scaling_squaring", "hybrid"}) {
        SCOPED_TRACE(method);
        const auto out = [&](const std::string& tag) { return (dir_ / (method + tag + ".exr")).string(); };
        for (const std::string tag : {"gpu", "cpu"}) {
            const Result r = run_ts(kRender + " --exp-method " + method + " --out " + out(tag) +
                                 (tag == "cpu" ? " --device cpu" : " --device vulkan"));
            ASSERT_EQ(r.exit_code, 0) << r.err;
            // Which path ran: "..., on cpu" or "..., on <device name>".
            EXPECT_EQ(r.out.find(", on cpu\n") != std::string::npos, tag == "cpu") << r.out;
            EXPECT_EQ(r.err.find("runs on the CPU"), std::string::npos) << r.err;
        }
        int wg = 0, wc = 0;
        const auto g = read_rgb_float(out("gpu"), wg), c = read_rgb_float(out("cpu"), wc);
        ASSERT_FALSE(g.empty());
        ASSERT_EQ(g.size(), c.size());
        EXPECT_EQ(wg, 101);
        double worst = 0;
        std::size_t over = 0;
        std::vector<double> rel;
        for (std::size_t i = 0; i < g.size(); ++i) {
            ASSERT_EQ(std::isnan(g[i]), std::isnan(c[i])) << i;
            if (std::isnan(g[i])) continue;
            const double e = std::abs(double(g[i]) - double(c[i])) / std::max(std::abs(double(c[i])), 1e-6);
            if (e > kMaxRel) ++over;
            else worst = std::max(worst, e);
        }
        std::printf("%s: GPU vs --cpu picture: worst rel %.2e, %zu of %zu channels beyond %.0e\n", method.c_str(),
                    worst, over, g.size(), kMaxRel);
        EXPECT_LE(double(over), kFlipFraction * double(g.size()));
    }
}

TEST_F(RenderGpuCli, NoVulkanTakesTheCpuPathUnlessVulkanWasAskedFor) {
    const std::string png = (dir_ / "map.png").string();
    const Result fallback = run_ts(kRender + " --directions 8 --out " + png, kNoVulkan);
    ASSERT_EQ(fallback.exit_code, 0) << fallback.err;
    EXPECT_NE(fallback.out.find(", on cpu\n"), std::string::npos) << fallback.out;
    EXPECT_TRUE(fs::exists(png));

    const Result asked = run_ts(kRender + " --directions 8 --device 0 --out " + png, kNoVulkan);
    EXPECT_EQ(asked.exit_code, 2) << asked.err;
    const Result both = run_ts(kRender + " --cpu --device 0 --out " + png);
    EXPECT_EQ(both.exit_code, 2);
    const Result bad_index = run_ts(kRender + " --device 99 --out " + png);
    EXPECT_EQ(bad_index.exit_code, 2) << bad_index.err;
    // An exponentiation the GPU lacks keeps the transfer on the CPU, with a note.
    const Result taylor = run_ts(kRender + " --directions 8 --exp-method taylor --device vulkan --out " + png);
    ASSERT_EQ(taylor.exit_code, 0) << taylor.err;
    EXPECT_NE(taylor.err.find("--exp-method taylor runs on the CPU"), std::string::npos) << taylor.err;
}

TEST_F(RenderGpuCli, RelightAndBenchRelightSayWhereTheyRan) {
    const Result relight = run_ts("relight " + ts::cli_test::kDem + ts::cli_test::kCrop + " --directions 8 --times "
                               "2025-06-21T08:00Z/2025-06-21T10:00Z/PT1H --device vulkan --out " +
                               (dir_ / "frames").string());
    ASSERT_EQ(relight.exit_code, 0) << relight.err;
    EXPECT_NE(relight.out.find("sky shading on "), std::string::npos) << relight.out;
    EXPECT_EQ(relight.out.find("sky shading on cpu"), std::string::npos) << relight.out;
    EXPECT_TRUE(fs::exists(dir_ / "frames" / "frame_0002_2025-06-21T1000Z.png"));

    const Result bench = run_ts("bench relight " + ts::cli_test::kDem + ts::cli_test::kCrop +
                                " --directions 8 --frames 2 --device vulkan --compare-cpu");
    ASSERT_EQ(bench.exit_code, 0) << bench.err;
    EXPECT_NE(bench.out.find("backend: "), std::string::npos) << bench.out;
    EXPECT_NE(bench.out.find("device / cpu time:"), std::string::npos) << bench.out;
}
