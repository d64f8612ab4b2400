// core/visibility/window_visibility_backend: a window of a larger grid given the larger grid's
// horizons and far sun shadows, on a synthetic grid. With a marched far field (built from a
// coarse copy, as for a grid never held whole) the backend gives what the window's exact sweep
// raised by the far field gives, for the core only; with the exact far field what the CPU
// backend gives for the window's receivers over the whole grid; the sun shadow hook gives the
// far field's limit_sun for the core.
#include "core/visibility/window_visibility_backend.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "core/util/error.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "tests/visibility/far_field_copies.hpp"
#include "tests/visibility/synthetic_terrain.hpp"

namespace ts::visibility {
namespace {

// A window with a 24-texel halo around its core, off-centre in a 256 x 256 grid of hills.
struct WindowCase {
    testing::Terrain terrain = testing::make_terrain(256, 256, 30.0, 30.0, testing::hills);
    ReceiverWindow window{80, 70, 112, 104}, core{104, 94, 64, 56};
    testing::OwnedGrid window_grid = testing::cut(terrain.grid, window);
    FarFieldOptions options = [] {
        FarFieldOptions o;
        o.start_texels = 24;
        o.threads = 2;
        return o;
    }();
    int shift = FarField::coarse_shift_for(options, 256, 256);
    testing::OwnedGrid coarse = testing::mean_level(terrain.grid, shift);
    FarField far{coarse.grid, shift, 256, 256, terrain.grid.dx_m, terrain.grid.dy_m,
                 testing::top_height(terrain.grid), options};
};

VisibilityRequest request() {
    VisibilityRequest r;
    r.horizon.directions = 16;
    r.horizon.threads = 2;
    r.log_sh = r.svf = true;
    return r;
}

TEST(WindowFarFieldVisibility, GivesTheCoreTheWindowsSweepRaisedByTheFarField) {
    const WindowCase s;
    const VisibilityRequest r = request();
    const VisibilityResult got = make_window_far_field_visibility(s.window, s.core, s.far)->compute(s.window_grid.grid, r);
    HorizonOptions ho = r.horizon;
    ho.window = {s.core.col0 - s.window.col0, s.core.row0 - s.window.row0, s.core.width, s.core.height};
    const HorizonSet alone = compute_horizons(s.window_grid.grid, ho);
    HorizonSet want = alone;
    s.far.raise(want, s.core, s.core, s.window_grid.grid, {s.window.col0, s.window.row0});
    ASSERT_EQ(got.horizons.width, s.window.width);
    ASSERT_EQ(got.horizons.height, s.window.height);
    ASSERT_EQ(got.svf.size(), std::size_t(s.window.width) * std::size_t(s.window.height));
    long raised = 0;
    for (int row = 0; row < s.window.height; ++row)
        for (int col = 0; col < s.window.width; ++col) {
            const int cc = col + s.window.col0 - s.core.col0, cr = row + s.window.row0 - s.core.row0;
            const bool in_core = cc >= 0 && cr >= 0 && cc < s.core.width && cr < s.core.height;
            const float svf = got.svf[std::size_t(row) * std::size_t(s.window.width) + std::size_t(col)];
            ASSERT_EQ(std::isnan(svf), !in_core) << col << ", " << row;
            for (int d = 0; d < 16; ++d) {
                const float a = got.horizons.at(d, col, row);
                if (!in_core) {
                    ASSERT_TRUE(std::isnan(a));
                    continue;
                }
                ASSERT_EQ(a, want.at(d, cc, cr)) << col << ", " << row << ", " << d;
                raised += a > alone.at(d, cc, cr);
            }
        }
    EXPECT_GT(raised, 0) << "the far field adds terrain the window lacks";
}

TEST(WindowFarFieldVisibility, ExactSweepsTheWindowOverTheWholeGrid) {
    const WindowCase s;
    VisibilityRequest r = request();
    const VisibilityResult got = WindowFarFieldVisibility(s.window, s.core, s.terrain.grid).compute(s.window_grid.grid, r);
    r.horizon.window = s.window;
    const VisibilityResult want = make_cpu_visibility_backend()->compute(s.terrain.grid, r);
    EXPECT_EQ(got.horizons.angle, want.horizons.angle);
    EXPECT_EQ(got.log_sh, want.log_sh);
    EXPECT_EQ(got.svf, want.svf);
}

// The hook as the renderer holds it: a std::function of a sun state with azimuth_deg and
// elevation_deg, as render::SunState.
TEST(FarFieldSunShadow, IsTheFarFieldsLimitSunForTheCore) {
    const WindowCase s;
    struct Sun {
        double azimuth_deg = 0, elevation_deg = 0;
    };
    const std::function<void(const Sun&, std::vector<float>&)> hook =
        far_field_sun_shadow(s.window, s.core, s.far, s.window_grid.grid);
    long lowered = 0;
    for (double azimuth : {90.0, 200.0, 300.0}) {
        const std::size_t n = std::size_t(s.window.width) * std::size_t(s.window.height);
        std::vector<float> got(n, 1.0f), want(n, 1.0f);
        hook(Sun{azimuth, 2.0}, got);
        s.far.limit_sun(azimuth, 2.0, SunSweepOptions{}.sun_radius_rad, s.window, s.core, s.terrain.grid, want.data());
        EXPECT_EQ(got, want) << azimuth;
        for (int row = 0; row < s.window.height; ++row)
            for (int col = 0; col < s.window.width; ++col) {
                const bool in_core = col + s.window.col0 >= s.core.col0 && row + s.window.row0 >= s.core.row0 &&
                                     col + s.window.col0 < s.core.col0 + s.core.width &&
                                     row + s.window.row0 < s.core.row0 + s.core.height;
                const float v = got[std::size_t(row) * std::size_t(s.window.width) + std::size_t(col)];
                if (!in_core) {
                    ASSERT_EQ(v, 1.0f) << "the halo is left as it is";
                }
                lowered += v < 1.0f;
            }
    }
    EXPECT_GT(lowered, 0);
}

TEST(WindowFarFieldVisibility, RefusesACoreOutsideItsWindowAndAnotherWindowsGrid) {
    const WindowCase s;
    EXPECT_THROW(WindowFarFieldVisibility(s.window, {70, 94, 64, 56}, s.far), InputError);
    EXPECT_THROW(WindowFarFieldVisibility({200, 70, 112, 104}, {210, 94, 64, 56}, s.far), InputError);
    const testing::OwnedGrid other = testing::cut(s.terrain.grid, {80, 70, 100, 104});
    EXPECT_THROW(WindowFarFieldVisibility(s.window, s.core, s.far).compute(other.grid, request()), InputError);
    EXPECT_THROW(FarFieldSunShadow(s.window, s.core, s.far, other.grid), InputError);
    std::vector<float> vis(10, 1.0f);
    EXPECT_THROW(far_field_sun_shadow(s.window, s.core, s.far, s.window_grid.grid)(180.0, 10.0, vis), InputError);
}

}  // namespace
}  // namespace ts::visibility
