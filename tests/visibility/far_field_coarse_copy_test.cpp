// The far field of a grid never held whole (core/visibility/far_field_horizons.hpp): built from
// a mean level computed elsewhere, with receiver heights from a window grid, against the far
// field built on the whole grid, on real DEMs.
//
// Bit for bit, not within a tolerance: the coarse copy is the same chain of
// terrain::downsample_2x2 steps whoever runs it (a finer copy only starts the chain later), the
// row spacing and the highest height are the grid's own, and a window's heights are the grid's
// texels copied, so every march reads the same floats and does the same double arithmetic.
#include "core/visibility/far_field_horizons.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/dem/fill_voids.hpp"
#include "core/dem/read_dem.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/terrain/height_pyramid.hpp"
#include "core/util/error.hpp"
#include "core/visibility/sun_sweep.hpp"
#include "core/visibility/visibility_grid.hpp"
#include "far_field_copies.hpp"

using namespace ts::visibility;
using ts::visibility::testing::cut;
using ts::visibility::testing::mean_level;
using ts::visibility::testing::OwnedGrid;
using ts::visibility::testing::top_height;
namespace fs = std::filesystem;

namespace {

bool same_bits(const float* a, const float* b, std::size_t n) {
    return std::memcmp(a, b, n * sizeof(float)) == 0;
}

// raise() and limit_sun() of `got` (receiver heights from the window grid) against `want` (the
// whole grid's), for the core of a window: raise on a set that starts below any horizon, so every
// far slope found shows; the sun at 8 azimuths and 3 low elevations. Returns how many sun
// values the far field lowered (the comparison is not empty).
long expect_same_far_field(const FarField& got, const FarField& want, const ts::terrain::HeightGrid& grid,
                           const ReceiverWindow& win, const ReceiverWindow& core) {
    const OwnedGrid window = cut(grid, win);
    const WindowOrigin at{win.col0, win.row0};
    HorizonSet a, b;
    a.width = b.width = win.width, a.height = b.height = win.height, a.directions = b.directions = 16;
    a.angle.resize(a.texels() * 16), b.angle.resize(b.texels() * 16);
    std::fill(a.angle.begin(), a.angle.end(), -1.5f), std::fill(b.angle.begin(), b.angle.end(), -1.5f);
    got.raise(a, win, core, window.grid, at);
    want.raise(b, win, core, grid);
    EXPECT_TRUE(same_bits(a.angle.data(), b.angle.data(), a.angle.size())) << "raise()";
    long lowered = 0;
    const double radius = SunSweepOptions{}.sun_radius_rad;
    for (double azimuth = 0; azimuth < 360; azimuth += 45)
        for (double elevation : {1.0, 4.0, 10.0}) {
            std::vector<float> va(std::size_t(win.width) * std::size_t(win.height), 1.0f), vb = va;
            got.limit_sun(azimuth, elevation, radius, win, core, window.grid, at, va.data());
            want.limit_sun(azimuth, elevation, radius, win, core, grid, vb.data());
            EXPECT_TRUE(same_bits(va.data(), vb.data(), va.size())) << "limit_sun() at " << azimuth << ", " << elevation;
            for (float v : va) lowered += v < 1.0f;
        }
    return lowered;
}

struct Grids {
    ts::dem::Dem dem;
    ts::terrain::HeightGrid filled;                  // voids filled (what a scene shades)
    std::unique_ptr<VisibilityGrid> with_holes;      // voids as NaN
};

Grids load(const std::string& name) {
    Grids g;
    g.dem = ts::dem::read_dem(fs::path(TS_SHARED_DATA) / "dem" / name);
    ts::dem::fill_voids(g.dem);
    g.filled = ts::terrain::metric_view(g.dem);
    g.with_holes = std::make_unique<VisibilityGrid>(g.dem);
    return g;
}

}  // namespace

// A 120 x 120 core in a window grown by 64 texels, the far field starting at the halo (the
// level-1 copy) and at 256 texels (level 3, tiles' default halo), from the level it reads and
// from finer ones.
TEST(FarFieldCoarseCopy, EqualsTheWholeGridsFarFieldBitForBit) {
    for (const std::string& name : std::vector<std::string>{"srtm3_N39E040_1000px.tif", "copernicus_N45E005_grenoble_500px.tif"}) {
        const Grids grids = load(name);
        for (const ts::terrain::HeightGrid* grid : {&grids.filled, &grids.with_holes->view()}) {
            constexpr int kCore = 120, kHalo = 64;
            const ReceiverWindow core{(grid->width - kCore) / 2, (grid->height - kCore) / 2, kCore, kCore};
            const ReceiverWindow win{core.col0 - kHalo, core.row0 - kHalo, kCore + 2 * kHalo, kCore + 2 * kHalo};
            for (double start : {double(kHalo), 256.0}) {
                FarFieldOptions fo;
                fo.start_texels = start;
                fo.threads = 2;
                const FarField whole(*grid, fo);
                const int shift = FarField::coarse_shift_for(fo, grid->width, grid->height);
                EXPECT_EQ(1 << shift, whole.coarse_scale());
                for (int copy_shift = shift; copy_shift >= std::max(0, shift - 2); --copy_shift) {
                    SCOPED_TRACE(name + (grid == &grids.filled ? " filled" : " with holes") + ", start " +
                                 std::to_string(start) + ", copy at level " + std::to_string(copy_shift) + " for " +
                                 std::to_string(shift));
                    const OwnedGrid coarse = mean_level(*grid, copy_shift);
                    const FarField far(coarse.grid, copy_shift, grid->width, grid->height, grid->dx_m, grid->dy_m,
                                       top_height(*grid), fo);
                    EXPECT_EQ(far.coarse_scale(), whole.coarse_scale());
                    EXPECT_EQ(far.bytes(), whole.bytes());
                    EXPECT_GT(expect_same_far_field(far, whole, *grid, win, core), 0);
                }
            }
        }
    }
}

// What a streaming pass relies on: the mean level computed band by band, on bands of 2^shift
// rows, is the whole grid's level.
TEST(FarFieldCoarseCopy, ALevelByBandsIsTheWholeGridsLevel) {
    const Grids grids = load("copernicus_N45E005_grenoble_500px.tif");
    const ts::terrain::HeightGrid& g = grids.with_holes->view();
    for (int shift : {1, 3}) {
        const OwnedGrid whole = mean_level(g, shift);
        std::vector<float> banded;
        const int band = 3 << shift;  // any multiple of 2^shift; the last band is shorter
        for (int row0 = 0; row0 < g.height; row0 += band) {
            const OwnedGrid rows = cut(g, {0, row0, g.width, std::min(band, g.height - row0)});
            const OwnedGrid level = mean_level(rows.grid, shift);
            banded.insert(banded.end(), level.z.begin(), level.z.end());
        }
        ASSERT_EQ(banded.size(), whole.z.size());
        EXPECT_TRUE(same_bits(banded.data(), whole.z.data(), banded.size())) << "level " << shift;
    }
}

// A copy coarser than the far field needs is read as it is.
TEST(FarFieldCoarseCopy, ReadsACoarserCopyAsItIs) {
    std::vector<float> z(512 * 512, 100.0f);
    const auto g = ts::terrain::HeightGrid::uniform(512, 512, z, 30, 30);
    FarFieldOptions fo;
    fo.start_texels = 64;
    const int shift = FarField::coarse_shift_for(fo, 512, 512);
    const OwnedGrid coarse = mean_level(g, shift + 2);
    const FarField far(coarse.grid, shift + 2, 512, 512, g.dx_m, g.dy_m, 100.0f, fo);
    EXPECT_EQ(far.coarse_scale(), 1 << (shift + 2));
}

TEST(FarFieldCoarseCopy, RefusesACopyOfAnotherSizeAndWindowsOffTheGrid) {
    std::vector<float> z(256 * 256, 0.0f);
    const auto g = ts::terrain::HeightGrid::uniform(256, 256, z, 30, 30);
    FarFieldOptions fo;
    fo.start_texels = 16;
    const OwnedGrid coarse = mean_level(g, 2);
    EXPECT_THROW(FarField(coarse.grid, 1, 256, 256, g.dx_m, g.dy_m, 0.0f, fo), ts::InputError);
    EXPECT_THROW(FarField(coarse.grid, 2, 300, 256, g.dx_m, g.dy_m, 0.0f, fo), ts::InputError);
    EXPECT_THROW(FarField(coarse.grid, 2, 256, 256, std::vector<double>(100, 30.0), g.dy_m, 0.0f, fo), ts::InputError);
    fo.samples_per_octave = 0;
    EXPECT_THROW(FarField::coarse_shift_for(fo, 256, 256), ts::InputError);
    fo.samples_per_octave = 4;
    const FarField far(coarse.grid, 2, 256, 256, g.dx_m, g.dy_m, 0.0f, fo);
    const OwnedGrid window = cut(g, {200, 200, 56, 56});
    HorizonSet set;
    set.width = set.height = 56, set.directions = 4;
    set.angle.resize(set.texels() * 4);
    // The window reaches past the grid's edge; then receivers outside the window grid.
    EXPECT_THROW(far.raise(set, {210, 210, 56, 56}, {210, 210, 56, 56}, window.grid, {210, 210}), ts::InputError);
    EXPECT_THROW(far.raise(set, {190, 190, 56, 56}, {190, 190, 20, 20}, window.grid, {200, 200}), ts::InputError);
    std::vector<float> vis(56 * 56, 1.0f);
    EXPECT_THROW(far.limit_sun(180, 10, 0.005, {190, 190, 56, 56}, {190, 190, 20, 20}, window.grid, {200, 200}, vis.data()),
                 ts::InputError);
    EXPECT_NO_THROW(far.raise(set, {200, 200, 56, 56}, {210, 210, 20, 20}, window.grid, {200, 200}));
}
