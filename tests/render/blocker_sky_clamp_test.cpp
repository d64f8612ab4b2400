// A mesh blocker only removes light (core/render/blocker_sky_clamp.hpp): a truck-like blob of
// overlapping spheres standing on flat ground under a uniform and an overcast sky, shaded on
// every path (fused fp16 and fp32, the backend's field, a specular sheen), never brightens a texel beyond its
// terrain-only radiance; the bound's bookkeeping on its own.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "core/light/overcast_sky.hpp"
#include "core/render/blocker_sky_clamp.hpp"
#include "core/render/frame_renderer.hpp"
#include "core/render/render_backend.hpp"
#include "tests/render/frame_stack.hpp"
#include "tests/render/uniform_sky.hpp"

namespace ts::render {
namespace {

// fp16 storage of T and the albedo (diffuse_shading.hpp) rounds each side by up to ~2.5e-4 of
// its terms: twice that, with a margin, between the render with and without the mesh.
constexpr double kBrighteningTolerance = 2e-3;

struct FlatScene {
    static constexpr int kSize = 121;
    std::vector<float> z = std::vector<float>(std::size_t(kSize) * kSize, 200.0f);
    terrain::HeightGrid grid = terrain::HeightGrid::uniform(kSize, kSize, z, 50.0, 50.0);
    MaterialRaster grey(float ks) const {
        MaterialRaster m = rule_materials(grid, terrain_normals(grid));
        std::fill(m.albedo_r.begin(), m.albedo_r.end(), 0.3f);
        std::fill(m.albedo_g.begin(), m.albedo_g.end(), 0.25f);
        std::fill(m.albedo_b.begin(), m.albedo_b.end(), 0.2f);
        std::fill(m.ks.begin(), m.ks.end(), ks);
        std::fill(m.alpha.begin(), m.alpha.end(), 8.0f);
        std::fill(m.water.begin(), m.water.end(), 0);
        return m;
    }
};

// The milk truck's shape at the gallery's scale: 8 x 3 x 3 spheres of 80 m, 60 m apart, the
// lowest row's centres 40 m below the ground (a deep contact shadow: many caps overlap, some
// centred below the tangent plane of the texels beside it). Without the bound the ground beside
// it comes out up to 12% (uniform sky) and 13% (overcast) brighter than without the blob.
blockers::SphereBlockers truck_blob() {
    blockers::SphereBlockers b;
    blockers::PlacedSpheres p;
    p.anchor = {60, 60};
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                p.spheres.push_back({{-210.0 + 60.0 * i, -60.0 + 60.0 * j, 160.0 + 80.0 * k}, 80.0});
    p.hierarchy = blockers::build_sphere_hierarchy(p.spheres);
    b.meshes.push_back(std::move(p));
    return b;
}

std::vector<glm::vec3> render(const FlatScene& f, const blockers::SphereBlockers* b, RendererOptions o,
                              const light::Sky& sky, float ks) {
    o.directions = 16, o.curvature = false, o.threads = 2, o.blockers = b;
    testing::FrameStack stack(f.grid, f.grey(ks), terrain_normals(f.grid), {}, o);
    if (b) EXPECT_NE(stack.state->blocker_sky_clamp(), nullptr);
    else EXPECT_EQ(stack.state->blocker_sky_clamp(), nullptr);
    const SunState sun{180.0, 40.0};
    std::vector<glm::vec3> out;
    stack->render(sky, sun, out);
    return out;
}

struct Brightening {
    double worst = -1;   // max over texels and channels of with / without - 1
    double centre = 0;   // with / without under the blob (red)
};

Brightening measure(const FlatScene& f, RendererOptions o, const light::Sky& sky, float ks) {
    const blockers::SphereBlockers b = truck_blob();
    const std::vector<glm::vec3> open = render(f, nullptr, o, sky, ks);
    const std::vector<glm::vec3> with = render(f, &b, o, sky, ks);
    Brightening m;
    for (std::size_t t = 0; t < open.size(); ++t)
        for (int c = 0; c < 3; ++c) m.worst = std::max(m.worst, double(with[t][c]) / double(open[t][c]) - 1.0);
    const std::size_t centre = f.grid.index(60, 60);
    m.centre = double(with[centre].x) / double(open[centre].x);
    return m;
}

TEST(BlockerSkyClamp, NoTexelIsBrighterThanItsTerrainAloneOnAnyPath) {
    const FlatScene f;
    const glm::dvec3 sun_dir = sun_direction({180.0, 40.0});
    const testing::UniformSky uniform(sun_dir, 0.0f);
    const light::OvercastSky overcast(1.0, 0.2, sun_dir);
    const std::unique_ptr<RenderBackend> cpu = make_cpu_backend(2);
    struct Path {
        const char* name;
        RendererOptions o;
        float ks = 0.0f;
    };
    std::vector<Path> paths(4);
    paths[0].name = "fused fp16";
    paths[1].name = "fused fp32", paths[1].o.shading_precision = DiffuseShading::Precision::single;
    paths[2].name = "backend field", paths[2].o.backend = cpu.get();
    paths[3].name = "fused fp16 with a Phong sheen (ks 0.3)", paths[3].ks = 0.3f;
    for (const Path& p : paths)
        for (const light::Sky* sky : {static_cast<const light::Sky*>(&uniform), static_cast<const light::Sky*>(&overcast)}) {
            const Brightening m = measure(f, p.o, *sky, p.ks);
            std::printf("%s, %s: largest brightening %+.5f, under the blob %.3f of the open ground\n", p.name,
                        sky == &uniform ? "uniform sky" : "overcast sky", m.worst, m.centre);
            EXPECT_LE(m.worst, kBrighteningTolerance) << p.name;
            // The bound leaves the shadow itself: the ground under the blob stays dark.
            EXPECT_LT(m.centre, 0.6) << p.name;
        }
}

TEST(BlockerSkyClamp, KeepsWhatLiesOutsideTheReplacedRectangleAndBoundsEachChannel) {
    BlockerSkyClamp clamp(9);
    // Two texels of a 10-wide grid: 12 (2, 1) and 57 (7, 5); D = 1 in coefficient 0, -1 in 1.
    auto transfers = [](std::size_t n, std::vector<float>& b, std::vector<float>& t) {
        b.assign(16 * n, 0.0f), t.assign(16 * n, 0.0f);
        for (std::size_t k = 0; k < n; ++k) b[k] = 1.0f, t[n + k] = 1.0f;
    };
    std::vector<float> b, t;
    transfers(2, b, t);
    const std::vector<std::uint32_t> first = {57, 12};
    const std::vector<glm::vec3> w = {glm::vec3(1.0f), glm::vec3(2.0f)};
    clamp.replace({0, 0, 10, 10}, 10, first, b.data(), t.data(), w.data());
    EXPECT_EQ(clamp.index(), (std::vector<std::uint32_t>{12, 57}));
    std::array<glm::vec3, 16> light{};
    light[0] = {1.0f, 0.0f, 2.0f};  // <D, L> = L_0 - L_1 per channel
    light[1] = {0.5f, 0.5f, 0.5f};
    std::vector<glm::vec3> out(100, glm::vec3(10.0f));
    clamp.apply(light, out.data(), 1);
    // Texel 12 (weight 2): r 10 - 2 * 0.5, g untouched (<D, L> < 0), b 10 - 2 * 1.5.
    EXPECT_FLOAT_EQ(out[12].x, 9.0f);
    EXPECT_FLOAT_EQ(out[12].y, 10.0f);
    EXPECT_FLOAT_EQ(out[12].z, 7.0f);
    EXPECT_FLOAT_EQ(out[57].x, 9.5f);
    EXPECT_FLOAT_EQ(out[3].x, 10.0f);
    // Replacing the rectangle holding texel 57 only: 12 stays, 57 goes, 56 comes.
    transfers(1, b, t);
    const std::vector<std::uint32_t> second = {56};
    clamp.replace({5, 5, 10, 6}, 10, second, b.data(), t.data(), w.data());
    EXPECT_EQ(clamp.index(), (std::vector<std::uint32_t>{12, 56}));
    EXPECT_DOUBLE_EQ(blocked_sky_term(1.09, 1.0), 1.0);
    EXPECT_DOUBLE_EQ(blocked_sky_term(0.4, 1.0), 0.4);
}

}  // namespace
}  // namespace ts::render
