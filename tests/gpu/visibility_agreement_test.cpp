// GPU visibility (gpu/visibility) against the CPU reference path (core/visibility): exact
// horizons, svf, sky_visible and log-SH on a 200 x 200 window of every shared DEM, receiver
// windows and bands of rows, voids; every case with the validation layer on.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/terrain/grid_crop.hpp"
#include "core/dem/read_dem.hpp"
#include "core/util/error.hpp"
#include "core/util/stopwatch.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/horizon_sh.hpp"
#include "core/visibility/sky_integrals.hpp"
#include "core/visibility/visibility_grid.hpp"
#include "gpu/visibility/gpu_visibility.hpp"
#include "tests/gpu/horizon_agreement.hpp"
#include "tests/gpu/validated_context.hpp"
#include "tests/visibility/synthetic_terrain.hpp"

namespace ts::gpu::visibility_agreement {
namespace {

namespace vis = ts::visibility;

using terrain::GridCrop;

GridCrop crop_of_file(const char* name, int size) {
    const dem::Dem dem = dem::read_dem(std::filesystem::path(TS_SHARED_DATA) / "dem" / name);
    const vis::VisibilityGrid full(dem);
    return terrain::centre_crop(full.view(), size, size);
}

// Tolerances (the figures measured on lavapipe are in the first test's output).
//
// Horizons: the GPU walks the same lines through the same samples in float instead of double.
// That moves a texel's horizon by < 3e-5 rad (measured on five DEMs and the whole N00E010
// tile: distances along lines in float, llvmpipe's atan 3.4e-6 rad off). But the CPU method has discontinuities that
// float can decide the other way, and then that one texel-azimuth differs by up to a few 1e-2:
//  - a blocker exactly `near field` (2 texels) behind a line sample joins the far field or not
//    (a position float puts a few metres off, 2e-5 of a 111 km texel of the 1-degree grid);
// So: texel-azimuths agree to kHorizonTol except at most kFlipFraction of them ("flips"), and
// the RMS over all of them stays below kHorizonTol (measured 2.6e-6 at most).
constexpr double kHorizonTol = 1e-4;    // rad
constexpr double kFlipFraction = 1e-4;  // measured 0 on five DEMs, 1e-5 on the 1-degree global grid
// svf and sky_visible: the target, 1e-4 absolute, on every texel (measured <= 5e-6, and
// 2.8e-5 with the global grid's flips). log-SH: coefficients up to ~8 summed from 32 slices in
// float, 1e-4 absolute on texels without a flip (measured 2.8e-5).
constexpr double kSvfTol = 1e-4;
constexpr double kShTol = 1e-4;

struct Comparison {
    double max_horizon = 0;  // over texel-azimuths that are not flips
    double rms_horizon = 0;  // over all texel-azimuths
    std::size_t flips = 0, compared = 0, nan_mismatches = 0;
    double max_svf = 0, max_sky = 0;  // over all texels
    double max_svf_unflipped = 0, max_sh = 0;  // over texels without a flip
};

struct CpuRun {
    vis::HorizonSet horizons;
    std::vector<float> svf, sky, log_sh;
    double ms = 0;
};

CpuRun run_cpu(const terrain::HeightGrid& grid, const vis::HorizonOptions& options) {
    const Stopwatch t0;
    CpuRun r;
    r.horizons = vis::compute_horizons(grid, options);
    r.svf = vis::svf_raster(r.horizons);
    r.sky = vis::sky_visible_raster(r.horizons);
    r.log_sh = vis::log_sh_raster(r.horizons);
    r.ms = t0.milliseconds();
    return r;
}

double abs_diff(float a, float b) { return std::abs(double(a) - double(b)); }

Comparison compare(const CpuRun& cpu, const visibility::Result& gpu) {
    Comparison c;
    const std::size_t texels = cpu.horizons.texels();
    const test_support::HorizonAgreement h =
        test_support::compare_horizons(cpu.horizons, gpu.horizons, kHorizonTol, "TS_GPU_VISIBILITY_VERBOSE");
    c.max_horizon = h.max, c.rms_horizon = h.rms;
    c.flips = h.flips, c.compared = h.compared, c.nan_mismatches = h.nan_mismatches;
    const std::vector<bool>& flipped = h.flipped;
    for (std::size_t t = 0; t < texels; ++t) {
        if (std::isnan(cpu.svf[t]) != std::isnan(gpu.svf[t]) || std::isnan(cpu.sky[t]) != std::isnan(gpu.sky_visible[t]))
            ++c.nan_mismatches;
        if (std::isnan(cpu.svf[t])) continue;
        c.max_svf = std::max(c.max_svf, abs_diff(cpu.svf[t], gpu.svf[t]));
        c.max_sky = std::max(c.max_sky, abs_diff(cpu.sky[t], gpu.sky_visible[t]));
        if (flipped[t]) continue;
        c.max_svf_unflipped = std::max(c.max_svf_unflipped, abs_diff(cpu.svf[t], gpu.svf[t]));
        for (int i = 0; i < 16; ++i) {
            const float a = cpu.log_sh[std::size_t(i) * texels + t], b = gpu.log_sh[std::size_t(i) * texels + t];
            if (std::isnan(a) != std::isnan(b)) ++c.nan_mismatches;
            else if (!std::isnan(a)) c.max_sh = std::max(c.max_sh, abs_diff(a, b));
        }
    }
    return c;
}

// Every texel within tolerance (flips counted, see above), next to voids too.
void expect_agreement(const Comparison& c) {
    EXPECT_EQ(c.nan_mismatches, 0u);
    EXPECT_LE(c.max_horizon, kHorizonTol);
    EXPECT_LE(c.rms_horizon, kHorizonTol);
    EXPECT_LE(double(c.flips), kFlipFraction * double(c.compared));
    EXPECT_LE(c.max_svf, kSvfTol);
    EXPECT_LE(c.max_sky, kSvfTol);
    EXPECT_LE(c.max_sh, kShTol);
}

std::string stage_list(const visibility::Result& r) {
    std::string s;
    for (const auto& st : r.stages) s += st.label + " " + std::to_string(int(std::lround(st.ms))) + " ";
    return s;
}

using GpuVisibilityTest = test_support::ValidatedTest;

TEST_F(GpuVisibilityTest, ExactHorizonsSvfAndShMatchTheCpuOnEverySharedDem) {
    const std::filesystem::path dir = std::filesystem::path(TS_SHARED_DATA) / "dem";
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 5u);
    double cpu_total = 0, gpu_total = 0;
    for (const auto& file : files) {
        SCOPED_TRACE(file.filename().string());
        const dem::Dem dem = dem::read_dem(file);
        const vis::VisibilityGrid full(dem);
        const GridCrop c = terrain::centre_crop(full.view(), 200, 200);
        vis::HorizonOptions options;
        options.directions = 32;
        const CpuRun cpu = run_cpu(c.grid, options);
        const Stopwatch t0;
        const auto gpu = visibility::compute(*context_, c.grid, {.horizon = options});
        const double gpu_ms = t0.milliseconds();
        const Comparison cmp = compare(cpu, gpu);
        std::printf("%-38s %3dx%-3d D=32 horizon max %.1e rms %.1e rad, flips %zu/%zu; svf %.1e sky %.1e "
                    "log-SH %.1e; cpu %.0f ms, gpu %.0f ms [ms: %s]\n",
                    file.filename().string().c_str(), c.grid.width, c.grid.height, cmp.max_horizon, cmp.rms_horizon,
                    cmp.flips, cmp.compared, cmp.max_svf, cmp.max_sky, cmp.max_sh, cpu.ms, gpu_ms,
                    stage_list(gpu).c_str());
        cpu_total += cpu.ms;
        gpu_total += gpu_ms;
        expect_agreement(cmp);
    }
    std::printf("all windows: cpu %.0f ms, gpu %.0f ms (gpu time / cpu time %.2f)\n", cpu_total, gpu_total,
                gpu_total / cpu_total);
}

TEST_F(GpuVisibilityTest, BandsOfRowsJoinIntoTheWholeWindowResult) {
    const GridCrop c = crop_of_file("srtm3_N39E040_1000px.tif", 120);
    visibility::Options options;
    options.horizon.directions = 16;
    const auto whole = visibility::compute(*context_, c.grid, options);
    options.max_band_rows = 37;  // 4 bands, the last one short
    const auto banded = visibility::compute(*context_, c.grid, options);
    EXPECT_EQ(whole.bands, 1);
    EXPECT_EQ(banded.bands, 4);
    // Same lines, same samples, same arithmetic: identical, not just close.
    EXPECT_EQ(whole.horizons.angle, banded.horizons.angle);
    EXPECT_EQ(whole.log_sh, banded.log_sh);
    EXPECT_EQ(whole.svf, banded.svf);
}

TEST_F(GpuVisibilityTest, HeightsSplitAcrossBuffersEqualTheWholeGridRun) {
    const GridCrop c = crop_of_file("srtm3_N39E040_1000px.tif", 120);
    visibility::Options options;
    options.horizon.directions = 16;
    const auto whole = visibility::compute(*context_, c.grid, options);
    // A storage buffer of 45 rows of heights: the heights in 3 buffers (45, 45, 30 rows), as a
    // grid larger than 128 MiB would be on lavapipe, and the receivers in bands of 50 rows.
    options.max_height_buffer_bytes = 45 * 120 * sizeof(float);
    options.max_band_rows = 50;
    const auto split = visibility::compute(*context_, c.grid, options);
    EXPECT_EQ(whole.bands, 1);
    EXPECT_EQ(split.bands, 3);
    // Same lines, same samples, same arithmetic whichever buffer a height comes from: identical.
    EXPECT_EQ(whole.horizons.angle, split.horizons.angle);
    EXPECT_EQ(whole.log_sh, split.log_sh);
    EXPECT_EQ(whole.svf, split.svf);
    EXPECT_EQ(whole.sky_visible, split.sky_visible);
    // Five buffers' worth of rows is more than the GPU path takes: a clear error, not a crash.
    options.max_height_buffer_bytes = 20 * 120 * sizeof(float);
    EXPECT_THROW(visibility::compute(*context_, c.grid, options), InputError);
}

TEST_F(GpuVisibilityTest, ReceiverWindowEqualsTheSameTexelsOfTheWholeGridAndTheCpu) {
    const GridCrop c = crop_of_file("copernicus_N45E005_grenoble_500px.tif", 120);
    visibility::Options options;
    options.horizon.directions = 16;
    const auto whole = visibility::compute(*context_, c.grid, options);
    // A window touching the grid's east edge: blockers still come from the whole grid.
    options.horizon.window = {.col0 = 70, .row0 = 30, .width = 50, .height = 40};
    const auto part = visibility::compute(*context_, c.grid, options);
    ASSERT_EQ(part.horizons.width, 50);
    ASSERT_EQ(part.horizons.height, 40);
    const CpuRun cpu = run_cpu(c.grid, options.horizon);
    for (int d = 0; d < 16; ++d)
        for (int r = 0; r < 40; ++r)
            for (int col = 0; col < 50; ++col) {
                ASSERT_EQ(part.horizons.at(d, col, r), whole.horizons.at(d, 70 + col, 30 + r)) << d << " " << col << " " << r;
                ASSERT_NEAR(part.horizons.at(d, col, r), cpu.horizons.at(d, col, r), kHorizonTol);
            }
    for (int r = 0; r < 40; ++r)
        for (int col = 0; col < 50; ++col)
            EXPECT_NEAR(part.svf[std::size_t(r) * 50 + col], cpu.svf[std::size_t(r) * 50 + col], kSvfTol);
}

TEST_F(GpuVisibilityTest, VoidsNeitherBlockNorReceiveAsOnTheCpu) {
    GridCrop c = crop_of_file("N00E011.hgt.zip", 100);
    // A 12 x 9 hole and a lone void texel: NaN receivers, and no surface there for blockers.
    for (int r = 40; r < 49; ++r)
        for (int col = 30; col < 42; ++col) c.z[std::size_t(r) * 100 + col] = std::nanf("");
    c.z[std::size_t(70) * 100 + 71] = std::nanf("");
    vis::HorizonOptions options;
    options.directions = 16;
    const CpuRun cpu = run_cpu(c.grid, options);
    const auto gpu = visibility::compute(*context_, c.grid, {.horizon = options});
    const Comparison cmp = compare(cpu, gpu);
    EXPECT_TRUE(std::isnan(gpu.horizons.at(3, 35, 44)));
    EXPECT_TRUE(std::isnan(gpu.svf[std::size_t(70) * 100 + 71]));
    EXPECT_TRUE(std::isnan(gpu.log_sh[std::size_t(70) * 100 + 71]));
    std::printf("voids: flips %zu/%zu, svf max %.1e (%.1e away from flips), sky %.1e\n", cmp.flips, cmp.compared,
                cmp.max_svf, cmp.max_svf_unflipped, cmp.max_sky);
    expect_agreement(cmp);
}

TEST_F(GpuVisibilityTest, NoCurvatureAndTwoLinesPerTexelAgreeToo) {
    const GridCrop c = crop_of_file("N00E010.hgt", 100);
    vis::HorizonOptions options;
    options.directions = 8;
    options.curvature = false;
    options.exact_lines_per_texel = 2;
    const CpuRun cpu = run_cpu(c.grid, options);
    const auto gpu = visibility::compute(*context_, c.grid, {.horizon = options});
    expect_agreement(compare(cpu, gpu));
}

// The grid's edges: a receiver on the edge facing out has nothing in front of it, one a texel
// or two inside has only its near field, and a void along the edge (a projected grid's rotated
// footprint) is an edge too. Lines through those texels have no far field yet while their
// neighbours one line spacing away do, and lines along a texel row or column pass the voids'
// centres: where the result hinges on rounding, double and float part. Square texels put the
// lines of azimuths 0, 45, 90, ... degrees through texel centres (up to rounding), the worst
// case. Every texel is compared, the edges included: svf and sky_visible within kEdgeSvfTol,
// the horizons' RMS within kEdgeHorizonRms, every texel-azimuth within kHorizonTol, no flips
// (measured on lavapipe: svf 2.4e-7, RMS 2.1e-7 rad, max 2.4e-6 rad). Without the near field
// the sweep decides the nearest blockers in float too, and a rare near tie flips (measured 1
// in 2e5 texel-azimuths): there the flip allowance of the DEM tests (kFlipFraction) applies.
constexpr double kEdgeSvfTol = 1e-5;
constexpr double kEdgeHorizonRms = 2e-6;  // rad

struct EdgeCase {
    const char* name;
    terrain::GridCrop grid;
    vis::HorizonOptions options;
    bool flips_allowed = false;
};

// Synthetic hills on 30 m square texels, 96 x 72.
terrain::GridCrop edge_hills(bool rotated_footprint) {
    const auto t = vis::testing::make_terrain(96, 72, 30, 30, vis::testing::hills);
    terrain::GridCrop c;
    c.z = t.z;
    const int w = 96, h = 72;
    if (rotated_footprint) {
        // As gdalwarp leaves a tile reprojected onto another grid: valid inside a rectangle
        // turned by 4 degrees (void wedges along all four edges, corners void), plus a void
        // bay cut into the west edge.
        const double a = 4.0 * std::numbers::pi / 180.0, ca = std::cos(a), sa = std::sin(a);
        for (int r = 0; r < h; ++r)
            for (int col = 0; col < w; ++col) {
                const double x = col - 0.5 * (w - 1), y = r - 0.5 * (h - 1);
                const double u = x * ca + y * sa, v = -x * sa + y * ca;
                if (std::abs(u) > 0.5 * w - 3 || std::abs(v) > 0.5 * h - 3)
                    c.z[std::size_t(r) * w + col] = std::nanf("");
            }
        for (int r = 30; r < 40; ++r)
            for (int col = 0; col < 12; ++col) c.z[std::size_t(r) * w + col] = std::nanf("");
    }
    c.grid = terrain::HeightGrid::uniform(w, h, c.z, 30, 30);
    return c;
}

TEST_F(GpuVisibilityTest, EveryTexelAgreesUpToTheGridEdgesAndAlongVoidsThatTouchThem) {
    std::vector<EdgeCase> cases;
    vis::HorizonOptions options;
    options.directions = 32;
    cases.push_back({"hills", edge_hills(false), options});
    cases.push_back({"hills, rotated footprint", edge_hills(true), options});
    options.exact_near_field_texels = 0;  // the pure sweep: the edge row itself has no near field
    cases.push_back({"hills, no near field", edge_hills(false), options, true});
    cases.push_back({"hills, rotated footprint, no near field", edge_hills(true), options, true});
    for (const EdgeCase& ec : cases) {
        SCOPED_TRACE(ec.name);
        const terrain::HeightGrid& g = ec.grid.grid;
        const CpuRun cpu = run_cpu(g, ec.options);
        const auto gpu = visibility::compute(*context_, g, {.horizon = ec.options});
        const test_support::HorizonAgreement h =
            test_support::compare_horizons(cpu.horizons, gpu.horizons, kHorizonTol, "TS_GPU_VISIBILITY_VERBOSE");
        double max_svf = 0, max_sky = 0, max_edge_svf = 0;
        std::size_t nan_mismatches = h.nan_mismatches, worst = 0;
        for (int r = 0; r < g.height; ++r)
            for (int col = 0; col < g.width; ++col) {
                const std::size_t t = std::size_t(r) * std::size_t(g.width) + std::size_t(col);
                nan_mismatches += std::isnan(cpu.svf[t]) != std::isnan(gpu.svf[t]);
                nan_mismatches += std::isnan(cpu.sky[t]) != std::isnan(gpu.sky_visible[t]);
                if (std::isnan(cpu.svf[t]) || std::isnan(gpu.svf[t])) continue;
                const double d = abs_diff(cpu.svf[t], gpu.svf[t]);
                if (d > max_svf) max_svf = d, worst = t;
                max_sky = std::max(max_sky, abs_diff(cpu.sky[t], gpu.sky_visible[t]));
                if (r < 3 || col < 3 || r >= g.height - 3 || col >= g.width - 3)
                    max_edge_svf = std::max(max_edge_svf, d);
            }
        std::printf(
            "%-40s horizon max %.1e rms %.1e rad, flips %zu/%zu; svf max %.1e (at %zu,%zu; within 3 texels "
            "of an edge %.1e) sky %.1e\n",
            ec.name, h.max, h.rms, h.flips, h.compared, max_svf, worst % std::size_t(g.width),
            worst / std::size_t(g.width), max_edge_svf, max_sky);
        EXPECT_EQ(nan_mismatches, 0u);
        if (ec.flips_allowed) {
            EXPECT_LE(double(h.flips), kFlipFraction * double(h.compared));
        } else {
            EXPECT_EQ(h.flips, 0u);
        }
        EXPECT_LE(h.max, kHorizonTol);
        EXPECT_LE(h.rms, kEdgeHorizonRms);
        EXPECT_LE(max_svf, kEdgeSvfTol);
        EXPECT_LE(max_sky, kEdgeSvfTol);
    }
}

// A projected grid: N00E010 warped to UTM 32N at 92 m as gdalwarp does it (a rotated
// footprint: row 0 void west of column 117), receivers in windows at its two northern corners.
// Blockers come from the whole grid, so every line through a window is walked in full: in the
// north-east window that includes lines of 1200 samples with Earth curvature whose far hull
// holds vertices a decimetre apart 35 km back, where a bisection of the hull goes wrong in
// float (vis_exact_sweep.comp's hull_query). Every texel of both windows, the edge rows
// included, agrees. A few seconds: only the lines through the windows are walked.
TEST_F(GpuVisibilityTest, ProjectedTileCornersAgreeOnEveryTexel) {
    const std::filesystem::path utm =
        std::filesystem::temp_directory_path() / ("ts_gpu_edges_utm_" + std::to_string(::getpid()) + ".tif");
    const std::string cmd = "gdalwarp -q -overwrite -t_srs EPSG:32632 -tr 92 92 -r bilinear -ot Int16 " +
                            (std::filesystem::path(TS_SHARED_DATA) / "dem" / "N00E010.hgt").string() + " " +
                            utm.string();
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    const dem::Dem dem = dem::read_dem(utm);
    std::filesystem::remove(utm);
    const vis::VisibilityGrid full(dem);
    const terrain::HeightGrid& g = full.view();
    ASSERT_EQ(g.width, 1211);
    ASSERT_EQ(g.height, 1203);
    ASSERT_TRUE(std::isnan(g.at(116, 0)) && !std::isnan(g.at(117, 0)));  // the footprint's corner
    for (const vis::ReceiverWindow win : {vis::ReceiverWindow{100, 0, 24, 4}, vis::ReceiverWindow{1195, 0, 16, 16}}) {
        SCOPED_TRACE(std::to_string(win.col0) + "," + std::to_string(win.row0));
        vis::HorizonOptions options;
        options.directions = 32;
        options.window = win;
        const CpuRun cpu = run_cpu(g, options);
        const auto gpu = visibility::compute(*context_, g, {.horizon = options});
        const test_support::HorizonAgreement a =
            test_support::compare_horizons(cpu.horizons, gpu.horizons, kHorizonTol, "TS_GPU_VISIBILITY_VERBOSE");
        double max_svf = 0;
        std::size_t nan_mismatches = a.nan_mismatches;
        for (std::size_t t = 0; t < cpu.svf.size(); ++t) {
            nan_mismatches += std::isnan(cpu.svf[t]) != std::isnan(gpu.svf[t]);
            if (!std::isnan(cpu.svf[t]) && !std::isnan(gpu.svf[t]))
                max_svf = std::max(max_svf, abs_diff(cpu.svf[t], gpu.svf[t]));
        }
        std::printf("UTM window %d,%d %dx%d: horizon max %.1e rms %.1e rad, flips %zu/%zu; svf max %.1e\n", win.col0,
                    win.row0, win.width, win.height, a.max, a.rms, a.flips, a.compared, max_svf);
        EXPECT_EQ(nan_mismatches, 0u);
        EXPECT_EQ(a.flips, 0u);
        EXPECT_LE(a.max, kHorizonTol);
        EXPECT_LE(a.rms, kEdgeHorizonRms);
        EXPECT_LE(max_svf, kEdgeSvfTol);
    }
}

TEST_F(GpuVisibilityTest, RaymarchDoesNotRunOnTheGpu) {
    const GridCrop c = crop_of_file("N00E010.hgt", 20);
    visibility::Options options;
    options.horizon.method = vis::HorizonMethod::raymarch;  // pyramid runs there: pyramid_agreement_test.cpp
    EXPECT_THROW(visibility::compute(*context_, c.grid, options), InputError);
}


// The whole N00E010 tile (1201^2, every blocker of the tile, no crop), GPU against CPU at
// D = 4 so it costs a few seconds; the timed whole-tile runs at D = 32 are
// `terrashade bench visibility N00E010.hgt --whole` (timing belongs in benchmarks).
TEST_F(GpuVisibilityTest, WholeTileAgrees) {
    const dem::Dem dem = dem::read_dem(std::filesystem::path(TS_SHARED_DATA) / "dem" / "N00E010.hgt");
    const vis::VisibilityGrid full(dem);
    vis::HorizonOptions options;
    options.directions = 4;
    const auto gpu = visibility::compute(*context_, full.view(), {.horizon = options});
    const CpuRun cpu = run_cpu(full.view(), options);
    const Comparison cmp = compare(cpu, gpu);
    std::printf("whole tile: horizon max %.1e rms %.1e rad, flips %zu/%zu; svf %.1e sky %.1e log-SH %.1e\n",
                cmp.max_horizon, cmp.rms_horizon, cmp.flips, cmp.compared, cmp.max_svf, cmp.max_sky, cmp.max_sh);
    expect_agreement(cmp);
}

}  // namespace
}  // namespace ts::gpu::visibility_agreement
