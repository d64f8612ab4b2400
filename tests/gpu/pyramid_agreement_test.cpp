// GPU pyramid method (gpu/visibility/gpu_pyramid) against the CPU (core/terrain/height_pyramid,
// core/visibility/pyramid_horizons.cpp): the mean pyramid's levels, and the horizons, svf,
// sky_visible and log-SH on a 200 x 200 crop of every shared DEM; bands, split height buffers,
// receiver windows, voids and schedules. Every case with the validation layer on.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/terrain/grid_crop.hpp"
#include "core/dem/read_dem.hpp"
#include "core/terrain/height_pyramid.hpp"
#include "core/util/error.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/horizon_sh.hpp"
#include "core/visibility/sky_integrals.hpp"
#include "core/visibility/visibility_grid.hpp"
#include "gpu/visibility/gpu_pyramid.hpp"
#include "gpu/visibility/gpu_visibility.hpp"
#include "tests/gpu/horizon_agreement.hpp"
#include "tests/gpu/validated_context.hpp"

namespace ts::gpu::pyramid_agreement {
namespace {

namespace vis = ts::visibility;

// Tolerances (the tests print the measured figures; those below are from lavapipe).
// Levels: the CPU sums a block's (at most four) floats exactly in double and rounds the mean
// once; the GPU keeps the exact sum as a float pair and rounds once from it. Measured: every
// texel of every level equal; a mean of three (a block with one void) could in principle land
// one float ulp away (double rounding on the CPU), hence 1 ulp.
constexpr int kLevelUlps = 1;
// Horizons: the GPU marches the same samples through the same levels in float (positions as an
// integer texel plus a float offset) instead of double, and llvmpipe's atan is ~3e-6 rad off.
// The march is continuous in the positions except where a sample lands within float rounding of
// the grid's edge or of a void's edge; there one texel-azimuth could differ by more ("flips").
// Measured on 200 x 200 crops of the six shared DEMs at D = 32: rms <= 1.1e-6 rad, max 4.9e-6,
// no flips; svf <= 6e-7, sky_visible <= 1.4e-6, log-SH <= 7.2e-6.
constexpr double kHorizonRms = 1e-5;   // rad, over all texel-azimuths (the target)
constexpr double kHorizonTol = 2e-5;   // rad, per texel-azimuth except flips
constexpr double kFlipFraction = 1e-5;
constexpr double kSvfTol = 1e-4;  // svf and sky_visible (the target), texels without a flip
constexpr double kShTol = 1e-4;   // log-SH coefficients, texels without a flip

using terrain::GridCrop;

GridCrop crop_of_file(const std::filesystem::path& file, int w, int h) {
    const dem::Dem dem = dem::read_dem(file);
    const vis::VisibilityGrid full(dem);
    return terrain::centre_crop(full.view(), w, h);
}
std::filesystem::path dem_file(const char* name) { return std::filesystem::path(TS_SHARED_DATA) / "dem" / name; }

std::vector<std::filesystem::path> every_dem() {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(TS_SHARED_DATA) / "dem"))
        files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

// Distance in float ulps (both finite).
long ulps(float a, float b) {
    std::int32_t ia, ib;
    std::memcpy(&ia, &a, 4);
    std::memcpy(&ib, &b, 4);
    if (ia < 0) ia = std::int32_t(0x80000000u) - ia;
    if (ib < 0) ib = std::int32_t(0x80000000u) - ib;
    return std::labs(long(ia) - long(ib));
}

struct LevelComparison {
    std::size_t texels = 0, unequal = 0, nan_mismatches = 0;
    long max_ulps = 0;
};

LevelComparison compare_levels(const terrain::HeightGrid& grid, const std::vector<std::vector<float>>& gpu) {
    const terrain::HeightPyramid cpu(grid);
    LevelComparison c;
    EXPECT_EQ(int(gpu.size()), cpu.level_count());
    for (int l = 0; l < std::min(int(gpu.size()), cpu.level_count()); ++l) {
        const auto& level = cpu.level(l);
        EXPECT_EQ(gpu[std::size_t(l)].size(), std::size_t(level.width) * std::size_t(level.height));
        for (int r = 0; r < level.height; ++r)
            for (int col = 0; col < level.width; ++col) {
                const float a = level.at(col, r), b = gpu[std::size_t(l)][std::size_t(r) * level.width + col];
                ++c.texels;
                if (std::isnan(a) || std::isnan(b)) {
                    c.nan_mismatches += std::isnan(a) != std::isnan(b);
                    continue;
                }
                if (a != b) ++c.unequal;
                c.max_ulps = std::max(c.max_ulps, ulps(a, b));
            }
    }
    return c;
}

struct CpuRun {
    vis::HorizonSet horizons;
    std::vector<float> svf, sky, log_sh;
};

CpuRun run_cpu(const terrain::HeightGrid& grid, const vis::HorizonOptions& options) {
    CpuRun r;
    r.horizons = vis::compute_horizons(grid, options);
    r.svf = vis::svf_raster(r.horizons);
    r.sky = vis::sky_visible_raster(r.horizons);
    r.log_sh = vis::log_sh_raster(r.horizons);
    return r;
}

struct Comparison {
    double max_horizon = 0, rms_horizon = 0;  // max over texel-azimuths that are not flips
    std::size_t flips = 0, compared = 0, nan_mismatches = 0;
    double max_svf = 0, max_sky = 0, max_sh = 0;  // over texels without a flip
};

double abs_diff(float a, float b) { return std::abs(double(a) - double(b)); }

Comparison compare(const CpuRun& cpu, const visibility::Result& gpu) {
    Comparison c;
    const std::size_t texels = cpu.horizons.texels();
    EXPECT_EQ(gpu.horizons.angle.size(), cpu.horizons.angle.size());
    const test_support::HorizonAgreement h =
        test_support::compare_horizons(cpu.horizons, gpu.horizons, kHorizonTol, "TS_GPU_PYRAMID_VERBOSE");
    c.max_horizon = h.max, c.rms_horizon = h.rms;
    c.flips = h.flips, c.compared = h.compared, c.nan_mismatches = h.nan_mismatches;
    const std::vector<bool>& flipped = h.flipped;
    for (std::size_t t = 0; t < texels; ++t) {
        if (std::isnan(cpu.svf[t]) != std::isnan(gpu.svf[t])) ++c.nan_mismatches;
        if (std::isnan(cpu.svf[t]) || flipped[t]) continue;
        c.max_svf = std::max(c.max_svf, abs_diff(cpu.svf[t], gpu.svf[t]));
        c.max_sky = std::max(c.max_sky, abs_diff(cpu.sky[t], gpu.sky_visible[t]));
        for (int i = 0; i < 16; ++i) {
            const float a = cpu.log_sh[std::size_t(i) * texels + t], b = gpu.log_sh[std::size_t(i) * texels + t];
            if (std::isnan(a) != std::isnan(b)) ++c.nan_mismatches;
            else if (!std::isnan(a)) c.max_sh = std::max(c.max_sh, abs_diff(a, b));
        }
    }
    return c;
}

void expect_agreement(const Comparison& c) {
    EXPECT_EQ(c.nan_mismatches, 0u);
    EXPECT_LE(c.rms_horizon, kHorizonRms);
    EXPECT_LE(c.max_horizon, kHorizonTol);
    EXPECT_LE(double(c.flips), kFlipFraction * double(c.compared));
    EXPECT_LE(c.max_svf, kSvfTol);
    EXPECT_LE(c.max_sky, kSvfTol);
    EXPECT_LE(c.max_sh, kShTol);
}

void print(const std::string& what, const Comparison& c) {
    std::printf("%-40s horizon rms %.1e max %.1e rad, flips %zu/%zu; svf %.1e sky %.1e log-SH %.1e\n", what.c_str(),
                c.rms_horizon, c.max_horizon, c.flips, c.compared, c.max_svf, c.max_sky, c.max_sh);
}

vis::HorizonOptions pyramid_options(int directions) {
    vis::HorizonOptions o;
    o.method = vis::HorizonMethod::pyramid;
    o.directions = directions;
    return o;
}

using GpuPyramidTest = test_support::ValidatedTest;

TEST_F(GpuPyramidTest, LevelsEqualTheCpuPyramidOnEverySharedDem) {
    const auto files = every_dem();
    ASSERT_GE(files.size(), 5u);
    for (const auto& file : files) {
        SCOPED_TRACE(file.filename().string());
        // Odd sizes: the last column and row of a level average fewer texels.
        const GridCrop c = crop_of_file(file, 301, 257);
        const LevelComparison cmp = compare_levels(c.grid, visibility::pyramid_levels(*context_, c.grid));
        std::printf("%-40s levels: %zu texels, %zu unequal, max %ld ulp\n", file.filename().string().c_str(),
                    cmp.texels, cmp.unequal, cmp.max_ulps);
        EXPECT_EQ(cmp.nan_mismatches, 0u);
        EXPECT_LE(cmp.max_ulps, kLevelUlps);
    }
}

TEST_F(GpuPyramidTest, LevelsWithVoidsAndSplitHeightsEqualTheCpuPyramid) {
    GridCrop c = crop_of_file(dem_file("N00E011.hgt.zip"), 123, 77);
    // A hole, a lone void, and a void-only 2x2 block at level 0 (a NaN texel at level 1).
    for (int r = 20; r < 31; ++r)
        for (int col = 40; col < 47; ++col) c.z[std::size_t(r) * 123 + col] = std::nanf("");
    c.z[std::size_t(60) * 123 + 99] = std::nanf("");
    for (int r = 50; r < 52; ++r)
        for (int col = 10; col < 12; ++col) c.z[std::size_t(r) * 123 + col] = std::nanf("");
    // Heights in 3 buffers of 30 rows (a grid above maxStorageBufferRange on lavapipe).
    const auto gpu = visibility::pyramid_levels(*context_, c.grid, 30 * 123 * sizeof(float));
    ASSERT_GE(gpu.size(), 2u);
    EXPECT_TRUE(std::isnan(gpu[1][std::size_t(25) * 62 + 5]));
    const LevelComparison cmp = compare_levels(c.grid, gpu);
    std::printf("voids, split heights: %zu texels, %zu unequal, max %ld ulp\n", cmp.texels, cmp.unequal, cmp.max_ulps);
    EXPECT_EQ(cmp.nan_mismatches, 0u);
    EXPECT_LE(cmp.max_ulps, kLevelUlps);
    // The same levels from one buffer of heights, bit for bit (NaN included).
    const auto whole = visibility::pyramid_levels(*context_, c.grid);
    ASSERT_EQ(whole.size(), gpu.size());
    for (std::size_t l = 0; l < gpu.size(); ++l) {
        ASSERT_EQ(whole[l].size(), gpu[l].size());
        EXPECT_EQ(std::memcmp(whole[l].data(), gpu[l].data(), gpu[l].size() * sizeof(float)), 0) << "level " << l;
    }
}

TEST_F(GpuPyramidTest, HorizonsSvfAndShMatchTheCpuOnEverySharedDem) {
    const auto files = every_dem();
    ASSERT_GE(files.size(), 5u);
    for (const auto& file : files) {
        SCOPED_TRACE(file.filename().string());
        const GridCrop c = crop_of_file(file, 200, 200);
        const vis::HorizonOptions options = pyramid_options(32);
        const CpuRun cpu = run_cpu(c.grid, options);
        const auto gpu = visibility::compute(*context_, c.grid, {.horizon = options});
        const Comparison cmp = compare(cpu, gpu);
        print(file.filename().string() + " D=32", cmp);
        expect_agreement(cmp);
    }
}

TEST_F(GpuPyramidTest, EverySchedulesAndNoCurvatureAgreeToo) {
    const GridCrop c = crop_of_file(dem_file("copernicus_N45E005_grenoble_500px.tif"), 110, 90);
    for (const char* schedule : {"fast", "balanced", "fine", "finest"})
        for (bool curvature : {true, false}) {
            vis::HorizonOptions options = pyramid_options(12);
            options.pyramid_schedule = schedule;
            options.curvature = curvature;
            const CpuRun cpu = run_cpu(c.grid, options);
            const Comparison cmp = compare(cpu, visibility::compute(*context_, c.grid, {.horizon = options}));
            print(std::string("grenoble ") + schedule + (curvature ? "" : " no curvature"), cmp);
            expect_agreement(cmp);
        }
}

TEST_F(GpuPyramidTest, BandsAndSplitHeightsEqualTheWholeRun) {
    const GridCrop c = crop_of_file(dem_file("srtm3_N39E040_1000px.tif"), 120, 120);
    visibility::Options options;
    options.horizon = pyramid_options(16);
    const auto whole = visibility::compute(*context_, c.grid, options);
    options.max_band_rows = 37;  // 4 bands, the last one short
    const auto banded = visibility::compute(*context_, c.grid, options);
    options.max_height_buffer_bytes = 45 * 120 * sizeof(float);  // heights in 3 buffers
    const auto split = visibility::compute(*context_, c.grid, options);
    EXPECT_EQ(whole.bands, 1);
    EXPECT_EQ(banded.bands, 4);
    // Same samples, same arithmetic: identical, not just close.
    for (const auto* r : {&banded, &split}) {
        EXPECT_EQ(whole.horizons.angle, r->horizons.angle);
        EXPECT_EQ(whole.log_sh, r->log_sh);
        EXPECT_EQ(whole.svf, r->svf);
        EXPECT_EQ(whole.sky_visible, r->sky_visible);
    }
    options.max_height_buffer_bytes = 20 * 120 * sizeof(float);  // 6 buffers: more than it takes
    EXPECT_THROW(visibility::compute(*context_, c.grid, options), InputError);
}

TEST_F(GpuPyramidTest, ReceiverWindowEqualsTheSameTexelsOfTheWholeGrid) {
    const GridCrop c = crop_of_file(dem_file("copernicus_N45E005_grenoble_500px.tif"), 120, 120);
    visibility::Options options;
    options.horizon = pyramid_options(16);
    const auto whole = visibility::compute(*context_, c.grid, options);
    options.horizon.window = {.col0 = 70, .row0 = 30, .width = 50, .height = 40};  // touching the east edge
    const auto part = visibility::compute(*context_, c.grid, options);
    ASSERT_EQ(part.horizons.width, 50);
    ASSERT_EQ(part.horizons.height, 40);
    for (int d = 0; d < 16; ++d)
        for (int r = 0; r < 40; ++r)
            for (int col = 0; col < 50; ++col)
                ASSERT_EQ(part.horizons.at(d, col, r), whole.horizons.at(d, 70 + col, 30 + r)) << d << " " << col;
    expect_agreement(compare(run_cpu(c.grid, options.horizon), part));
}

TEST_F(GpuPyramidTest, VoidsNeitherBlockNorReceiveAsOnTheCpu) {
    GridCrop c = crop_of_file(dem_file("N00E011.hgt.zip"), 100, 100);
    for (int r = 40; r < 49; ++r)
        for (int col = 30; col < 42; ++col) c.z[std::size_t(r) * 100 + col] = std::nanf("");
    c.z[std::size_t(70) * 100 + 71] = std::nanf("");
    const vis::HorizonOptions options = pyramid_options(16);
    const CpuRun cpu = run_cpu(c.grid, options);
    const auto gpu = visibility::compute(*context_, c.grid, {.horizon = options});
    EXPECT_TRUE(std::isnan(gpu.horizons.at(3, 35, 44)));
    EXPECT_TRUE(std::isnan(gpu.svf[std::size_t(70) * 100 + 71]));
    const Comparison cmp = compare(cpu, gpu);
    print("N00E011 with voids", cmp);
    expect_agreement(cmp);
}

// The whole N00E010 tile (1201^2, 2 bands at D = 32), GPU against CPU at D = 4 so it costs a few
// seconds; TS_GPU_PYRAMID_WHOLE_DIRECTIONS=32 gives the figures at D = 32 (for reports). The timed
// whole-tile runs are `terrashade bench visibility N00E010.hgt --whole --whole-method pyramid`.
TEST_F(GpuPyramidTest, WholeTileAgrees) {
    const dem::Dem dem = dem::read_dem(dem_file("N00E010.hgt"));
    const vis::VisibilityGrid full(dem);
    const char* env = std::getenv("TS_GPU_PYRAMID_WHOLE_DIRECTIONS");
    const vis::HorizonOptions options = pyramid_options(env ? std::atoi(env) : 4);
    const auto gpu = visibility::compute(*context_, full.view(), {.horizon = options});
    const Comparison cmp = compare(run_cpu(full.view(), options), gpu);
    print("whole N00E010 D=" + std::to_string(options.directions) + " (" + std::to_string(gpu.bands) + " bands)", cmp);
    expect_agreement(cmp);
}

TEST_F(GpuPyramidTest, BadOptionsAreInputErrors) {
    const GridCrop c = crop_of_file(dem_file("N00E010.hgt"), 20, 20);
    visibility::Options options;
    options.horizon = pyramid_options(8);
    options.horizon.pyramid_schedule = "nonsense";
    EXPECT_THROW(visibility::compute(*context_, c.grid, options), InputError);
    options.horizon.pyramid_schedule = "balanced";
    options.horizon.directions = 0;
    EXPECT_THROW(visibility::compute(*context_, c.grid, options), InputError);
    options.horizon.directions = 8;
    options.horizon.window = {.col0 = 15, .row0 = 0, .width = 10, .height = 5};
    EXPECT_THROW(visibility::compute(*context_, c.grid, options), InputError);
}

}  // namespace
}  // namespace ts::gpu::pyramid_agreement
