// A moving mesh (ShadingState::move_mesh, relight --mesh-path): after a move only the old and
// new footprints' rectangle is recomputed, and the frame equals a state computed from scratch
// with the mesh in its new place; on the fused (fp16, fp32) and the backend paths.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "core/render/frame_renderer.hpp"
#include "core/render/render_backend.hpp"
#include "core/visibility/blocker_footprint.hpp"
#include "core/visibility/blocker_sun_shadow.hpp"
#include "tests/render/frame_stack.hpp"
#include "tests/render/uniform_sky.hpp"

namespace ts::render {
namespace {

// The moved state's texels come from the same functions on the same inputs as the fresh
// state's: float rounding at most (measured: bit for bit).
constexpr double kMovedVsFreshTolerance = 1e-5;

struct Hills {
    static constexpr int kW = 140, kH = 110;
    std::vector<float> z;
    terrain::HeightGrid grid;
    Hills() : z(std::size_t(kW) * kH) {
        for (int r = 0; r < kH; ++r)
            for (int c = 0; c < kW; ++c)
                z[std::size_t(r) * kW + c] = float(300.0 + 60.0 * std::sin(c * 0.07) * std::cos(r * 0.05) + 0.8 * c);
        grid = terrain::HeightGrid::uniform(kW, kH, z, 20.0, 20.0);
    }
    MaterialRaster materials() const {
        MaterialRaster m = rule_materials(grid, terrain_normals(grid));
        std::fill(m.ks.begin(), m.ks.end(), 0.0f);
        std::fill(m.water.begin(), m.water.end(), 0);
        return m;
    }
};

// An aircraft-sized cluster of spheres anchored at texel (col, row), 150 m above the datum's 300 m.
blockers::PlacedSpheres aircraft_at(double col, double row) {
    blockers::PlacedSpheres p;
    p.anchor = {col, row};
    p.spheres = {{{0.0, 0.0, 520.0}, 14.0}, {{18.0, 4.0, 522.0}, 9.0}, {{-17.0, -3.0, 519.0}, 10.0}};
    p.hierarchy = blockers::build_sphere_hierarchy(p.spheres);
    return p;
}

blockers::SphereBlockers scene_at(double col, double row) {
    blockers::SphereBlockers b;
    b.meshes.push_back(aircraft_at(col, row));
    return b;
}

RendererOptions options_for(const blockers::SphereBlockers* b) {
    RendererOptions o;
    o.directions = 16, o.curvature = false, o.threads = 2, o.blockers = b;
    return o;
}

double relative(const glm::vec3& a, const glm::vec3& b) {
    double worst = 0;
    for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(a[c]) - double(b[c])) / std::max(1e-6, double(std::abs(b[c]))));
    return worst;
}

TEST(MovingBlocker, AMoveRecomputesOnlyTheFootprintsAndEqualsAFreshState) {
    const Hills hills;
    const SunState sun{230.0, 30.0};
    const testing::UniformSky sky(sun_direction(sun), 2.0f);
    const std::unique_ptr<RenderBackend> cpu = make_cpu_backend(2);
    for (int path = 0; path < 3; ++path) {
        const blockers::SphereBlockers start = scene_at(40, 50), end = scene_at(95, 60);
        RendererOptions o = options_for(&start);
        if (path == 1) o.shading_precision = DiffuseShading::Precision::single;
        if (path == 2) o.backend = cpu.get();
        testing::FrameStack moving(hills.grid, hills.materials(), terrain_normals(hills.grid), {}, o);
        std::vector<glm::vec3> before, after, fresh_frame, whole;
        moving->render(sky, sun, before);
        const visibility::TexelRect rect = moving.state->move_mesh(0, end.meshes[0]);
        moving->render(sky, sun, after);
        o.blockers = &end;
        testing::FrameStack fresh(hills.grid, hills.materials(), terrain_normals(hills.grid), {}, o);
        fresh->render(sky, sun, fresh_frame);
        // The rectangle is the two sky footprints' bounds; outside it and the two sun footprints
        // the frame does not change at all.
        const double min_sine = blockers::min_cap_sine(start.options.min_solid_angle_sr);
        const visibility::TexelRect a = visibility::sky_footprint(hills.grid, start.meshes[0], min_sine);
        const visibility::TexelRect b = visibility::sky_footprint(hills.grid, end.meshes[0], min_sine);
        EXPECT_EQ(rect.col0, std::min(a.col0, b.col0));
        EXPECT_EQ(rect.col1, std::max(a.col1, b.col1));
        EXPECT_EQ(rect.row0, std::min(a.row0, b.row0));
        EXPECT_EQ(rect.row1, std::max(a.row1, b.row1));
        EXPECT_LT(rect.texels(), (long long)hills.grid.width * hills.grid.height);
        const visibility::TexelRect sun_a =
            visibility::BlockerSunShadow(hills.grid, start, 0.0, 1).footprint(0, sun.azimuth_deg, sun.elevation_deg);
        const visibility::TexelRect sun_b =
            visibility::BlockerSunShadow(hills.grid, end, 0.0, 1).footprint(0, sun.azimuth_deg, sun.elevation_deg);
        // The bounce's sun part reads the sun of the terrain a texel sees, out to the gather's
        // radius: around the sun footprints the mesh's shadow changes that, a little.
        const int reach = int(std::ceil(o.bounce.gather.radius_texels)) + 1;
        auto grown = [reach](visibility::TexelRect x) {
            x.col0 -= reach, x.row0 -= reach, x.col1 += reach, x.row1 += reach;
            return x;
        };
        const visibility::TexelRect bounce_a = grown(sun_a), bounce_b = grown(sun_b);
        long long changed = 0, changed_outside = 0, bounced = 0;
        double worst = 0, worst_bounced = 0;
        for (int r = 0; r < hills.grid.height; ++r)
            for (int c = 0; c < hills.grid.width; ++c) {
                const std::size_t t = hills.grid.index(c, r);
                const bool differs = before[t] != after[t];
                changed += differs;
                const bool footprints = rect.contains(c, r) || sun_a.contains(c, r) || sun_b.contains(c, r);
                if (differs && !footprints) {
                    if (bounce_a.contains(c, r) || bounce_b.contains(c, r)) {
                        ++bounced;
                        worst_bounced = std::max(worst_bounced, relative(after[t], before[t]));
                    } else {
                        ++changed_outside;
                    }
                }
                worst = std::max(worst, relative(after[t], fresh_frame[t]));
            }
        std::printf("path %d: move recomputed %lld of %d texels; %lld texels changed (%lld by the bounce alone, "
                    "at most %.3g); moved vs fresh worst %.3g\n",
                    path, rect.texels(), hills.grid.width * hills.grid.height, changed, bounced, worst_bounced, worst);
        EXPECT_GT(changed, 50);
        EXPECT_EQ(changed_outside, 0);
        EXPECT_LE(worst_bounced, 0.02);
        EXPECT_LE(worst, kMovedVsFreshTolerance);
        // The whole grid's recompute gives the same frame.
        moving.state->recompute_blockers();
        moving->render(sky, sun, whole);
        double worst_whole = 0;
        for (std::size_t t = 0; t < whole.size(); ++t) worst_whole = std::max(worst_whole, relative(whole[t], after[t]));
        EXPECT_LE(worst_whole, kMovedVsFreshTolerance);
        // Moving back restores the first frame.
        moving.state->move_mesh(0, start.meshes[0]);
        std::vector<glm::vec3> back;
        moving->render(sky, sun, back);
        double worst_back = 0;
        for (std::size_t t = 0; t < back.size(); ++t) worst_back = std::max(worst_back, relative(back[t], before[t]));
        EXPECT_LE(worst_back, kMovedVsFreshTolerance);
    }
}

}  // namespace
}  // namespace ts::render
