// The far field (core/visibility/far_field_horizons.hpp): a window's exact horizons raised by
// the far field against the exact horizons over the whole grid, for the window's core, on real
// DEMs; and the raise matters (the window alone misses what lies beyond it).
#include "core/visibility/far_field_horizons.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/dem/read_dem.hpp"
#include "core/util/error.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/sky_integrals.hpp"
#include "core/visibility/visibility_grid.hpp"

using namespace ts::visibility;
namespace fs = std::filesystem;

namespace {

// A rectangle of a grid as a grid of its own (heights copied, row spacing kept).
struct Window {
    std::vector<float> z;
    ts::terrain::HeightGrid grid;
};

Window window_cut(const ts::terrain::HeightGrid& g, const ReceiverWindow& w) {
    Window out;
    out.z.resize(std::size_t(w.width) * std::size_t(w.height));
    for (int r = 0; r < w.height; ++r)
        for (int c = 0; c < w.width; ++c) out.z[std::size_t(r) * w.width + c] = g.at(w.col0 + c, w.row0 + r);
    out.grid.width = w.width, out.grid.height = w.height;
    out.grid.z = out.z;
    out.grid.dx_m.assign(g.dx_m.begin() + w.row0, g.dx_m.begin() + w.row0 + w.height);
    out.grid.dy_m.assign(g.dy_m.begin() + w.row0, g.dy_m.begin() + w.row0 + w.height);
    return out;
}

struct Difference {
    double angle_rms = 0, angle_max = 0, angle_above = 0, svf_rms = 0, svf_max = 0;
};

// Over the core's receivers: `got` holds the window's receivers, `want` the core's.
Difference compare(const HorizonSet& got, const ReceiverWindow& win, const HorizonSet& want, const ReceiverWindow& core) {
    Difference d;
    const std::vector<float> svf_got = svf_raster(got, WedgeRule::linear, 2), svf_want = svf_raster(want, WedgeRule::linear, 2);
    double a2 = 0, s2 = 0;
    long n = 0, m = 0;
    for (int r = 0; r < core.height; ++r)
        for (int c = 0; c < core.width; ++c) {
            const int gc = core.col0 - win.col0 + c, gr = core.row0 - win.row0 + r;
            const std::size_t kg = std::size_t(gr) * got.width + gc, kw = std::size_t(r) * want.width + c;
            for (int k = 0; k < want.directions; ++k) {
                const double signed_e = double(got.at(k, gc, gr)) - want.at(k, c, r);
                const double e = std::abs(signed_e);
                if (std::isnan(e)) continue;
                d.angle_above = std::max(d.angle_above, signed_e);
                a2 += e * e, ++n, d.angle_max = std::max(d.angle_max, e);
            }
            const double e = std::abs(double(svf_got[kg]) - svf_want[kw]);
            if (std::isnan(e)) continue;
            s2 += e * e, ++m, d.svf_max = std::max(d.svf_max, e);
        }
    d.angle_rms = std::sqrt(a2 / double(std::max(1L, n)));
    d.svf_rms = std::sqrt(s2 / double(std::max(1L, m)));
    return d;
}

struct Case {
    std::string dem;
    double max_angle_rms;  // radians, raised against the whole grid's
    double min_gain;       // the window alone's angle RMS over the raised one's
};

}  // namespace

// A 120 x 120 core in a window grown by a 64-texel halo, 16 azimuths: the far field (balanced)
// brings the core's horizons to within the stated RMS of the whole grid's, and closer than the
// window alone by the stated gain (what blocks without a far field would show). What is left
// is mostly the exact sweep's own: its lines fall at other offsets in a window than on the
// whole grid (the largest differences, up to ~0.12 rad at cliffs, are there with or without the
// far field). svf hardly sees terrain that far (its weight falls with sin^2 of the elevation).
TEST(FarField, RaisesAWindowsHorizonsToTheWholeGrids) {
    for (const Case& k :
         {Case{"srtm3_N39E040_1000px.tif", 0.008, 3.0}, Case{"copernicus_N45E005_grenoble_500px.tif", 0.008, 1.2}}) {
        const ts::dem::Dem dem = ts::dem::read_dem(fs::path(TS_SHARED_DATA) / "dem" / k.dem);
        const VisibilityGrid vgrid(dem);
        const ts::terrain::HeightGrid& grid = vgrid.view();
        constexpr int kCore = 120, kHalo = 64;
        const ReceiverWindow core{(grid.width - kCore) / 2, (grid.height - kCore) / 2, kCore, kCore};
        const ReceiverWindow win{core.col0 - kHalo, core.row0 - kHalo, kCore + 2 * kHalo, kCore + 2 * kHalo};
        HorizonOptions ho;
        ho.directions = 16;
        ho.threads = 2;
        ho.window = core;
        const HorizonSet whole = compute_horizons(grid, ho);
        const Window w = window_cut(grid, win);
        ho.window = {};
        HorizonSet set = compute_horizons(w.grid, ho);
        const Difference alone = compare(set, win, whole, core);
        FarFieldOptions fo;
        fo.start_texels = kHalo;
        fo.threads = 2;
        const FarField far(grid, fo);
        EXPECT_GE(far.coarse_scale(), 2) << "the far field never reads the grid itself";
        far.raise(set, win, core, grid);
        const Difference raised = compare(set, win, whole, core);
        SCOPED_TRACE(k.dem + ": window alone svf rms " + std::to_string(alone.svf_rms) + " max " +
                     std::to_string(alone.svf_max) + ", angle rms " + std::to_string(alone.angle_rms) + " max " + std::to_string(alone.angle_max) + "; raised svf rms " + std::to_string(raised.svf_rms) + " max " +
                     std::to_string(raised.svf_max) + ", angle rms " + std::to_string(raised.angle_rms) + " max " +
                     std::to_string(raised.angle_max) + " above " + std::to_string(raised.angle_above));
        EXPECT_LE(raised.angle_rms, k.max_angle_rms);
        EXPECT_GE(alone.angle_rms, k.min_gain * raised.angle_rms);
        EXPECT_LE(raised.angle_max, alone.angle_max + 1e-6) << "the far field adds no error of its own beyond the sweep's";
        EXPECT_LE(raised.svf_rms, 0.001);
        EXPECT_LE(raised.svf_max, 0.01);
    }
}

TEST(FarField, RefusesBadOptionsAndAForeignGrid) {
    std::vector<float> z(64 * 64, 0.0f), other(32 * 32, 0.0f);
    const auto g = ts::terrain::HeightGrid::uniform(64, 64, z, 30, 30);
    FarFieldOptions fo;
    fo.start_texels = 0;
    EXPECT_THROW(FarField(g, fo), ts::InputError);
    fo.start_texels = 8;
    fo.samples_per_octave = 0;
    EXPECT_THROW(FarField(g, fo), ts::InputError);
    fo.samples_per_octave = 4;
    const FarField far(g, fo);
    HorizonSet set;
    set.width = set.height = 32, set.directions = 4;
    set.angle.resize(set.texels() * 4);
    const auto h = ts::terrain::HeightGrid::uniform(32, 32, other, 30, 30);
    EXPECT_THROW(far.raise(set, {0, 0, 32, 32}, {0, 0, 32, 32}, h), ts::InputError);
    EXPECT_THROW(far.raise(set, {0, 0, 32, 32}, {16, 16, 32, 32}, g), ts::InputError);
}

// Flat ground sees no far terrain above it (curvature drops it): the set is unchanged.
TEST(FarField, LeavesFlatGroundAlone) {
    std::vector<float> z(256 * 256, 100.0f);
    const auto g = ts::terrain::HeightGrid::uniform(256, 256, z, 30, 30);
    FarFieldOptions fo;
    fo.start_texels = 16;
    const FarField far(g, fo);
    HorizonSet set;
    set.width = set.height = 64, set.directions = 8;
    set.angle.resize(set.texels() * 8);
    std::fill(set.angle.begin(), set.angle.end(), 0.0f);
    far.raise(set, {96, 96, 64, 64}, {96, 96, 64, 64}, g);
    for (float a : set.angle) ASSERT_EQ(a, 0.0f);
}
