// `terrashade visibility --device vulkan` against `--device cpu`: the same outputs
// within the GPU path's tolerances (tests/gpu/visibility_agreement_test.cpp states them), the
// CPU fallbacks (a method the GPU lacks, no Vulkan at all) and the errors of --device.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/dem/read_dem.hpp"
#include "tests/cli/cli_support.hpp"
#include "tests/cli/frame_pixels.hpp"

namespace fs = std::filesystem;

namespace {

using ts::cli_test::kNoVulkan;
using ts::cli_test::kSharedDems;
using ts::cli_test::Result;
using ts::cli_test::run_ts;

// 121 x 121 texels of the Gabon tile (as visibility_cli_test.cpp).
const std::string kWindow = "visibility " + kSharedDems + "N00E010.hgt --crop 10.45,0.45,10.55,0.55";

// Every band of a float GeoTIFF, band-interleaved by pixel.
std::vector<float> read_all_bands(const fs::path& path, int& bands) {
    ts::raster::FloatPixels f = ts::cli_test::read_float_pixels(path);
    bands = f.channels;
    return std::move(f.data);
}

double max_abs_diff(const std::vector<float>& a, const std::vector<float>& b) {
    double m = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::isnan(a[i]) || std::isnan(b[i])) {
            if (std::isnan(a[i]) != std::isnan(b[i])) return INFINITY;
            continue;
        }
        m = std::max(m, std::abs(double(a[i]) - double(b[i])));
    }
    return m;
}

class VisibilityGpuCli : public ::testing::Test {
protected:
    fs::path dir_ = ts::cli_test::temp_root() /
                    ::testing::UnitTest::GetInstance()->current_test_info()->name();
    void SetUp() override { fs::create_directories(dir_); }
};

}  // namespace

TEST_F(VisibilityGpuCli, VulkanAgreesWithCpu) {
    const auto out = [&](const std::string& tag, const std::string& what) { return (dir_ / (tag + what)).string(); };
    for (const std::string tag : {"vulkan", "cpu"}) {
        const Result r = run_ts(kWindow + " --directions 16 --svf " + out(tag, "svf.tif") + " --sky-visible " +
                             out(tag, "sky.tif") + " --log-sh " + out(tag, "lsh.tif") + " --horizons " +
                             out(tag, "hz.tif") + " --device " + tag);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        // Where each stage ran is said on stdout ("horizons (exact) on cpu: ..." or "... on <device>").
        EXPECT_EQ(r.out.find("horizons (exact) on cpu") != std::string::npos, tag == "cpu") << r.out;
        EXPECT_EQ(r.out.find("on cpu") != std::string::npos, tag == "cpu") << r.out;
    }
    for (const std::string what : {"svf.tif", "sky.tif", "lsh.tif", "hz.tif"}) {
        SCOPED_TRACE(what);
        int bands_gpu = 0, bands_cpu = 0;
        const auto g = read_all_bands(out("vulkan", what), bands_gpu);
        const auto c = read_all_bands(out("cpu", what), bands_cpu);
        ASSERT_FALSE(g.empty());
        ASSERT_EQ(g.size(), c.size());
        EXPECT_EQ(bands_gpu, bands_cpu);
        // svf and sky_visible: the target 1e-4 absolute; log-SH: 1e-4 (float sums of 16 slices);
        // horizons in degrees: 1e-4 rad = 0.0057 deg (this window has no flips; measured 5e-4 deg).
        const double tol = what == "hz.tif" ? 0.0057 : 1e-4;
        EXPECT_LE(max_abs_diff(g, c), tol);
    }
    // Same georeferencing and layout as the CPU output.
    const auto a = ts::dem::read_dem(out("vulkan", "svf.tif")), b = ts::dem::read_dem(out("cpu", "svf.tif"));
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.georef.crs().epsg(), b.georef.crs().epsg());
}

// The default (--device auto) takes the path `terrashade devices` says it takes, for the reason
// it gives; --verbose says so.
TEST_F(VisibilityGpuCli, DefaultTakesThePathDevicesNames) {
    const Result devices = run_ts("devices");
    ASSERT_EQ(devices.exit_code, 0) << devices.err;
    const std::string key = "--device auto (every command's default): ";
    const auto at = devices.out.find(key);
    ASSERT_NE(at, std::string::npos) << devices.out;
    const std::string reason = devices.out.substr(at + key.size(), devices.out.find('\n', at) - at - key.size());
    const Result r = run_ts(kWindow + " --directions 8 --verbose --svf " + (dir_ / "svf.tif").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("(auto: " + reason + ")"), std::string::npos) << r.out << "\nreason: " << reason;
    const bool cpu_path = reason.find("the CPU path") != std::string::npos;
    EXPECT_EQ(r.out.find("device: cpu (") != std::string::npos, cpu_path) << r.out;
}

TEST_F(VisibilityGpuCli, WhatTheDeviceLacksRunsOnTheCpuAndSaysSo) {
    const Result r = run_ts(kWindow + " --directions 8 --method raymarch --device vulkan --svf " +
                         (dir_ / "p.tif").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("horizons (raymarch) on cpu"), std::string::npos) << r.out;
    const Result constant = run_ts(kWindow + " --directions 8 --wedges constant --device vulkan --svf " +
                                (dir_ / "c.tif").string());
    ASSERT_EQ(constant.exit_code, 0) << constant.err;
    EXPECT_NE(constant.out.find("svf (constant wedges) on cpu"), std::string::npos) << constant.out;
    EXPECT_EQ(constant.out.find("horizons (exact) on cpu"), std::string::npos) << constant.out;
}

// The pyramid method runs on the device and agrees with the CPU (tolerances of
// tests/gpu/pyramid_agreement_test.cpp: svf 1e-4).
TEST_F(VisibilityGpuCli, PyramidRunsOnTheDeviceAndAgreesWithCpu) {
    const auto out = [&](const std::string& tag) { return (dir_ / (tag + "svf.tif")).string(); };
    for (const std::string tag : {"vulkan", "cpu"}) {
        const Result r = run_ts(kWindow + " --directions 8 --method pyramid --svf " + out(tag) + " --device " + tag);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(r.out.find("horizons (pyramid) on cpu") != std::string::npos, tag == "cpu") << r.out;
    }
    int bands_gpu = 0, bands_cpu = 0;
    const auto g = read_all_bands(out("vulkan"), bands_gpu), c = read_all_bands(out("cpu"), bands_cpu);
    ASSERT_FALSE(g.empty());
    ASSERT_EQ(g.size(), c.size());
    EXPECT_LE(max_abs_diff(g, c), 1e-4);
}

TEST_F(VisibilityGpuCli, NoVulkanTakesTheCpuPathUnlessVulkanWasAskedFor) {
    const std::string svf = (dir_ / "svf.tif").string();
    const Result fallback = run_ts(kWindow + " --directions 8 --verbose --svf " + svf, kNoVulkan);
    ASSERT_EQ(fallback.exit_code, 0) << fallback.err;
    EXPECT_NE(fallback.out.find("device: cpu (auto: "), std::string::npos) << fallback.out;
    EXPECT_TRUE(fs::exists(svf));

    for (const std::string device : {"0", "vulkan"}) {
        const Result asked = run_ts(kWindow + " --directions 8 --device " + device + " --svf " + svf, kNoVulkan);
        EXPECT_EQ(asked.exit_code, 2) << device;
        EXPECT_NE(asked.err.find("mesa-vulkan-drivers"), std::string::npos) << asked.err;
    }
    const Result both = run_ts(kWindow + " --cpu --device 0 --svf " + svf);
    EXPECT_EQ(both.exit_code, 2);
    const Result bad_index = run_ts(kWindow + " --device 99 --svf " + svf);
    EXPECT_EQ(bad_index.exit_code, 2) << bad_index.err;
    const Result bad_word = run_ts(kWindow + " --device gpu --svf " + svf);
    EXPECT_EQ(bad_word.exit_code, 2) << bad_word.err;
    EXPECT_NE(bad_word.err.find("give auto, cpu, vulkan or a device index"), std::string::npos) << bad_word.err;
}
