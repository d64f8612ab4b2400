// The CPU VisibilityBackend answers every request whole, with the results of the functions it
// is made of (compute_horizons, visibility_products, the per-texel constant-wedge rasters), and
// says where each stage ran.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/util/error.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/visibility_backend.hpp"
#include "core/visibility/visibility_products.hpp"
#include "tests/visibility/synthetic_terrain.hpp"

namespace ts::visibility {
namespace {

TEST(VisibilityBackend, CpuGivesWhatTheFunctionsGive) {
    const testing::Terrain t = testing::make_terrain(40, 30, 30.0, 30.0, testing::hills);
    VisibilityRequest r;
    r.horizon.directions = 16;
    r.log_sh = r.svf = r.sky_visible = true;
    const VisibilityResult got = make_cpu_visibility_backend()->compute(t.grid, r);
    const HorizonSet set = compute_horizons(t.grid, r.horizon);
    const VisibilityProducts p = visibility_products(set, {});
    EXPECT_EQ(got.horizons.angle, set.angle);
    EXPECT_EQ(got.log_sh, p.log_sh);
    EXPECT_EQ(got.svf, p.svf);
    EXPECT_EQ(got.sky_visible, p.sky_visible);
    ASSERT_EQ(got.stages.size(), 2u);
    EXPECT_EQ(got.path(), "cpu");
    EXPECT_EQ(got.stages[1].label, "log-SH, svf, sky_visible");
}

TEST(VisibilityBackend, LeavesWhatWasNotAskedForEmptyAndIntegratesConstantWedgesPerTexel) {
    const testing::Terrain t = testing::make_terrain(24, 20, 30.0, 30.0, testing::hills);
    VisibilityRequest r;
    r.horizon.directions = 8;
    r.svf = true;
    r.wedges = WedgeRule::constant;
    const VisibilityResult got = make_cpu_visibility_backend()->compute(t.grid, r);
    EXPECT_TRUE(got.log_sh.empty());
    EXPECT_TRUE(got.sky_visible.empty());
    const std::vector<float> expected = svf_raster(compute_horizons(t.grid, r.horizon), WedgeRule::constant);
    ASSERT_EQ(got.svf.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(got.svf[i], expected[i]) << i;
    ASSERT_EQ(got.stages.size(), 2u);
    EXPECT_EQ(got.stages[1].label, "svf (constant wedges)");
}

TEST(VisibilityBackend, CompleteOnCpuFillsOnlyWhatIsMissing) {
    const testing::Terrain t = testing::make_terrain(16, 16, 30.0, 30.0, testing::hills);
    VisibilityRequest r;
    r.horizon.directions = 8;
    r.svf = r.sky_visible = true;
    VisibilityResult partial;
    partial.horizons = compute_horizons(t.grid, r.horizon);
    partial.svf.assign(partial.horizons.texels(), 0.25f);  // as if a device had computed it
    partial.stages.push_back({"horizons (exact), svf", "some device", 0.0});
    complete_on_cpu(t.grid, r, partial);
    EXPECT_EQ(partial.svf[0], 0.25f);
    EXPECT_EQ(partial.sky_visible.size(), partial.horizons.texels());
    EXPECT_EQ(partial.path(), "some device");
    ASSERT_EQ(partial.stages.size(), 2u);
    EXPECT_EQ(partial.stages[1].label, "sky_visible");
    EXPECT_EQ(partial.stages[1].path, "cpu");
}

TEST(VisibilityBackend, RefusesABadRequestBeforeAnyWork) {
    const testing::Terrain t = testing::make_terrain(8, 8, 30.0, 30.0, testing::hills);
    VisibilityRequest r;
    r.horizon.directions = 2;
    r.log_sh = true;
    EXPECT_THROW(make_cpu_visibility_backend()->compute(t.grid, r), InputError);
    r.horizon.directions = 0;
    r.log_sh = false;
    EXPECT_THROW(make_cpu_visibility_backend()->compute(t.grid, r), InputError);
}

}  // namespace
}  // namespace ts::visibility
