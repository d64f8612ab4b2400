// The exact sweep's lane-parallel far field (core/visibility/sweep_lanes.hpp) against the scalar
// sweep: bit-identical far-field sums and horizon planes on real DEM crops (geographic,
// projected, with voids) and synthetic grids with voids, edges, windows and odd sizes.
#include "core/visibility/sweep_lanes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/dem/read_dem.hpp"
#include "core/terrain/grid_crop.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/exact_azimuth.hpp"
#include "core/visibility/visibility_grid.hpp"
#include "synthetic_terrain.hpp"
#include "tests/support/shared_data.hpp"

using namespace ts::visibility;
using ts::visibility::testing::make_terrain;
namespace fs = std::filesystem;

namespace {

std::uint32_t bits(float v) {
    std::uint32_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

// Texels whose float bits differ (NaN payloads included), with the first one for the message.
struct Mismatch {
    long count = 0;
    std::size_t first = 0;
};
Mismatch compare_bits(std::span<const float> a, std::span<const float> b) {
    Mismatch m;
    EXPECT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
        if (bits(a[i]) != bits(b[i]) && m.count++ == 0) m.first = i;
    return m;
}

// Exact horizons with the lane sweep on and off: identical planes, bit for bit.
void expect_same_horizons(const ts::terrain::HeightGrid& grid, HorizonOptions o, const std::string& what) {
    o.method = HorizonMethod::exact;
    o.threads = 2;
    o.exact_simd_lines = true;
    const HorizonSet lanes = exact_horizons(grid, o);
    o.exact_simd_lines = false;
    const HorizonSet scalar = exact_horizons(grid, o);
    const Mismatch m = compare_bits(lanes.angle, scalar.angle);
    EXPECT_EQ(m.count, 0) << what << ": first at plane index " << m.first << " lanes " << lanes.angle[m.first]
                          << " scalar " << scalar.angle[m.first];
}

// Far-field sums of every azimuth of one sweep, lanes then scalar remainder versus scalar
// alone: identical, and the lane path must have taken lines (unless the CPU lacks AVX-512).
void expect_same_sums(const ts::terrain::HeightGrid& grid, const HorizonOptions& o, const std::string& what) {
    const ExactAzimuthSweep sweep(grid, o);
    HorizonOptions off = o;
    off.exact_simd_lines = false;
    const ExactAzimuthSweep scalar_sweep(grid, off);
    long lane_lines = 0;
    for (int d = 0; d < o.directions; ++d) {
        const SweepPlan plan = sweep.plan(azimuth_rad(d, o.directions));
        FarFieldSums lanes = sweep.make_sums(), scalar = sweep.make_sums();
        // The lane sweep through the hook (lines [n_min, n_max]), then the scalar sweep alone.
        sweep.sweep_far_field(plan, plan.n_min, plan.n_max + 1, lanes);
        scalar_sweep.sweep_far_field(plan, plan.n_min, plan.n_max + 1, scalar);
        lane_lines += (plan.lines() / 8) * 8;
        const Mismatch ms = compare_bits(lanes.sum, scalar.sum), mw = compare_bits(lanes.weight, scalar.weight);
        const Mismatch me = compare_bits(lanes.empty_weight, scalar.empty_weight);
        EXPECT_EQ(ms.count, 0) << what << " azimuth " << d << ": sums differ first at " << ms.first;
        EXPECT_EQ(mw.count, 0) << what << " azimuth " << d << ": weights differ first at " << mw.first;
        EXPECT_EQ(me.count, 0) << what << " azimuth " << d << ": empty weights differ first at " << me.first;
    }
    if (sweep_lanes_supported()) {
        EXPECT_GT(lane_lines, 0) << what;
    }
}


// Voids: a block, a diagonal streak, single texels and a void on the grid's edge.
void punch_voids(std::vector<float>& z, int w, int h) {
    auto at = [&](int c, int r) -> float& { return z[std::size_t(r) * w + c]; };
    for (int r = h / 3; r < h / 3 + 5 && r < h; ++r)
        for (int c = w / 4; c < w / 4 + 7 && c < w; ++c) at(c, r) = NAN;
    for (int k = 0; k < std::min(w, h) / 2; ++k) at(w / 2 + k / 2, h / 2 + k - k / 3) = NAN;
    at(3, 5) = NAN;
    at(w - 1, h / 2) = NAN;
    at(w / 2, 0) = NAN;
    at(0, h - 1) = NAN;
}

}  // namespace

TEST(SweepLanes, RealDemCropsBitIdentical) {
    for (const std::string name : {"N00E010.hgt", "copernicus_N45E005_grenoble_500px.tif", "srtm3_N39E040_1000px.tif",
                                   "etopo1_global_1deg.tif", "nodata_3x3.tif"}) {
        SCOPED_TRACE(name);
        const ts::dem::Dem dem = ts::dem::read_dem(ts::test::shared_dem(name));
        const VisibilityGrid vgrid(dem);
        const ts::terrain::GridCrop crop = ts::terrain::centre_crop(vgrid.view(), 150, 120);
        HorizonOptions o;
        o.directions = 32;
        expect_same_horizons(crop.grid, o, name);
        expect_same_sums(crop.grid, o, name);
    }
}

// The whole etopo grid (geographic, pole rows where the lines bend hardest): odd azimuths too.
TEST(SweepLanes, GlobalGridWithPoles) {
    const ts::dem::Dem dem = ts::dem::read_dem(ts::test::shared_dem("etopo1_global_1deg.tif"));
    const VisibilityGrid vgrid(dem);
    HorizonOptions o;
    o.directions = 13;
    expect_same_horizons(vgrid.view(), o, "etopo1 whole");
}

TEST(SweepLanes, SyntheticVoidsEdgesWindowsAndOptions) {
    auto t = make_terrain(97, 83, 30.0, 30.0, ts::visibility::testing::hills);
    punch_voids(t.z, 97, 83);
    HorizonOptions o;
    o.directions = 37;  // no azimuth on an axis but the first
    expect_same_horizons(t.grid, o, "voids");
    expect_same_sums(t.grid, o, "voids");
    o.curvature = false;
    o.exact_lines_per_texel = 2;
    expect_same_horizons(t.grid, o, "voids, 2 lines per texel, no curvature");
    o.exact_near_field_texels = 0;  // no delay: the queue drains at once
    expect_same_horizons(t.grid, o, "voids, pure sweep");
    o = HorizonOptions{};
    o.directions = 24;
    o.window = ReceiverWindow{10, 7, 41, 30};  // the sweep stops past the window
    expect_same_horizons(t.grid, o, "window");
    expect_same_sums(t.grid, o, "window");
    // Anisotropic texels (more rows than columns per metre) and a tall thin grid.
    auto a = make_terrain(40, 130, 90.0, 25.0, ts::visibility::testing::hills);
    o = HorizonOptions{};
    o.directions = 32;
    expect_same_horizons(a.grid, o, "anisotropic");
    // Tiny grids: fewer lines than a group, a 2-texel axis.
    for (auto [w, h] : {std::pair{2, 2}, std::pair{9, 2}, std::pair{2, 11}, std::pair{5, 4}}) {
        auto s = make_terrain(w, h, 30.0, 30.0, ts::visibility::testing::hills);
        expect_same_horizons(s.grid, o, "tiny " + std::to_string(w) + "x" + std::to_string(h));
    }
}

// A grid that is all void but one row: lines run through voids from end to end.
TEST(SweepLanes, MostlyVoid) {
    auto t = make_terrain(60, 50, 30.0, 30.0, ts::visibility::testing::hills);
    for (int r = 0; r < 50; ++r)
        if (r != 20)
            for (int c = 0; c < 60; ++c)
                if ((c + r) % 7 != 0) t.z[std::size_t(r) * 60 + c] = NAN;
    HorizonOptions o;
    o.directions = 16;
    expect_same_horizons(t.grid, o, "mostly void");
}

// The lane function itself: it takes whole groups (none on a CPU without AVX-512), and its sums
// plus the scalar remainder are the scalar sums (a uniform 30 m grid: the near field of 2 texels
// is a 60 m delay).
TEST(SweepLanes, DirectCallTakesWholeGroups) {
    auto t = make_terrain(70, 64, 30.0, 30.0, ts::visibility::testing::hills);
    punch_voids(t.z, 70, 64);
    HorizonOptions off;
    off.exact_simd_lines = false;
    const ExactAzimuthSweep scalar(t.grid, off);
    const RowMetrics metrics(t.grid);
    const sweep_geometry::SweepSetup setup{t.grid,
                                           metrics,
                                           scalar.window(),
                                           curvature_factor(true),
                                           off.exact_lines_per_texel,
                                           off.exact_near_field_texels * 30.0};
    for (int d = 0; d < 20; ++d) {
        const SweepPlan plan = scalar.plan(azimuth_rad(d, 20));
        FarFieldSums lanes = scalar.make_sums(), reference = scalar.make_sums();
        const long n = sweep_lines_simd(setup, plan, plan.n_min, plan.n_max + 1, lanes);
        EXPECT_EQ(n, plan.n_min + (sweep_lanes_supported() ? plan.lines() / 8 * 8 : 0)) << "azimuth " << d;
        scalar.sweep_far_field(plan, n, plan.n_max + 1, lanes);
        scalar.sweep_far_field(plan, plan.n_min, plan.n_max + 1, reference);
        EXPECT_EQ(compare_bits(lanes.sum, reference.sum).count, 0) << "azimuth " << d;
        EXPECT_EQ(compare_bits(lanes.weight, reference.weight).count, 0) << "azimuth " << d;
        EXPECT_EQ(compare_bits(lanes.empty_weight, reference.empty_weight).count, 0) << "azimuth " << d;
    }
}
