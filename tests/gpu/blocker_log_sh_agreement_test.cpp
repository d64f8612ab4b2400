// The sphere blockers' log-SH on the Vulkan device (blocker_log_sh.comp) against the CPU kernel
// (core/blockers/sphere_log_sh_kernel.hpp): both run the same sh_shared.h formulas in float over
// every sphere at every receiver, so they differ by rounding (GPU sqrt and division may be a
// few ulp off): within 1e-4 of the largest coefficient. The validation layer stays silent.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/blockers/sphere_hierarchy.hpp"
#include "core/blockers/sphere_log_sh_kernel.hpp"
#include "core/visibility/visibility_backend.hpp"
#include "gpu/visibility/gpu_blocker_log_sh.hpp"
#include "gpu/visibility/gpu_visibility_backend.hpp"
#include "tests/gpu/validated_context.hpp"

namespace ts::gpu::visibility {
namespace {

using blockers::RatioAttenuation;
using blockers::Sphere;

class GpuBlockerLogShTest : public test_support::ValidatedTest {};

// Receivers on a bumpy 60 x 50 m patch with tilted normals, spheres of 0.3-4 m over it (some
// touching the ground, so receivers fall inside them), one of them straddling the horizon.
struct Scene {
    std::vector<glm::vec3> receivers, normals;
    std::vector<Sphere> spheres;
};

Scene make_scene(int receivers, int spheres, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> ux(0.0f, 60.0f), uy(0.0f, 50.0f), tilt(-0.5f, 0.5f);
    std::uniform_real_distribution<double> cx(10.0, 50.0), cy(10.0, 40.0), cz(0.0, 25.0), rr(0.3, 4.0);
    Scene s;
    for (int i = 0; i < receivers; ++i) {
        const float x = ux(rng), y = uy(rng);
        s.receivers.emplace_back(x, y, 0.5f * std::sin(0.3f * x) * std::cos(0.2f * y));
        s.normals.push_back(glm::normalize(glm::vec3(tilt(rng), tilt(rng), 1.0f)));
    }
    for (int i = 0; i < spheres; ++i) s.spheres.push_back({{cx(rng), cy(rng), cz(rng)}, rr(rng)});
    s.spheres.push_back({{-200.0, 25.0, 0.0}, 30.0});  // far to the west, half below the horizon
    return s;
}

void expect_agrees(const Context& context, const Scene& s, const RatioAttenuation& options) {
    const std::size_t n = s.receivers.size();
    std::vector<float> gpu(16 * n, 0.0f), cpu(16 * n, 0.0f);
    for (std::size_t k = 0; k < gpu.size(); ++k) gpu[k] = cpu[k] = 0.001f * float(k % 7);  // it adds
    const float log_eps = -1.0f;
    GpuBlockerLogSh(context).add(s.receivers, s.normals, s.spheres, log_eps, options, gpu);
    const blockers::SphereLanes lanes(s.spheres);
    for (std::size_t t = 0; t < n; ++t) {
        float add[16] = {};
        blockers::accumulate_sphere_lanes(lanes, s.receivers[t], s.normals[t], log_eps, options, add);
        for (int i = 0; i < 16; ++i) cpu[std::size_t(i) * n + t] += add[i];
    }
    float scale = 0.0f;
    for (float v : cpu) scale = std::max(scale, std::abs(v));
    ASSERT_GT(scale, 0.1f);  // the spheres do shadow the receivers
    double worst = 0.0;
    for (std::size_t k = 0; k < gpu.size(); ++k) {
        ASSERT_TRUE(std::isfinite(gpu[k])) << k;
        worst = std::max(worst, double(std::abs(gpu[k] - cpu[k])));
    }
    EXPECT_LE(worst, 1e-4 * scale) << "largest coefficient " << scale;
}

TEST_F(GpuBlockerLogShTest, AgreesWithTheCpuKernelWithAndWithoutAttenuation) {
    const Scene s = make_scene(3000, 150, 5);
    for (bool cull : {true, false})
        for (bool ratio : {true, false}) {
            RatioAttenuation o;
            o.cull_lower_hemisphere = cull, o.solid_angle_ratio = ratio;
            SCOPED_TRACE(::testing::Message() << "cull " << cull << " ratio " << ratio);
            expect_agrees(*context_, s, o);
        }
}

TEST_F(GpuBlockerLogShTest, FiveHundredOverlappingSpheresStayFiniteAndAgree) {
    // 500 spheres piled within a few metres of the receivers: the ratio keeps the sum bounded.
    Scene s = make_scene(500, 0, 9);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    for (int i = 0; i < 500; ++i) s.spheres.push_back({{30.0 + u(rng), 25.0 + u(rng), 6.0 + u(rng)}, 2.0});
    expect_agrees(*context_, s, {});
}

TEST_F(GpuBlockerLogShTest, MismatchedSizesAreRefused) {
    const Scene s = make_scene(10, 3, 1);
    std::vector<float> wrong(16 * 9);
    EXPECT_THROW(GpuBlockerLogSh(*context_).add(s.receivers, s.normals, s.spheres, -1.0f, {}, wrong),
                 std::invalid_argument);
}

TEST_F(GpuBlockerLogShTest, TheVulkanBackendAddsMeshesAsTheCpuBackendDoes) {
    // The visibility seam with meshes: the Vulkan backend accumulates the spheres on the device
    // (no culling: the default), the CPU backend with its kernel; the log-SH agrees to float
    // rounding and the stage says where it ran. One mesh, then two with overlapping footprints
    // and their own anchors, the second low and large (receivers inside its spheres: the ratio
    // attenuation over both meshes' caps at once). A window off the grid's corner and a void
    // texel in the footprint too.
    const int w = 80, h = 70;
    std::vector<float> z(std::size_t(w) * h);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r) * w + c] = float(200.0 + 8.0 * std::sin(0.2 * c) * std::cos(0.15 * r));
    z[std::size_t(36) * w + 41] = std::numeric_limits<float>::quiet_NaN();
    const terrain::HeightGrid grid = terrain::HeightGrid::uniform(w, h, z, 10.0, 10.0);
    blockers::PlacedSpheres m;
    m.anchor = {40.0, 35.0};
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    for (int i = 0; i < 60; ++i) m.spheres.push_back({{u(rng), 0.3 * u(rng), 240.0 + 0.2 * u(rng)}, 1.5});
    m.hierarchy = blockers::build_sphere_hierarchy(m.spheres);
    blockers::PlacedSpheres low;
    low.anchor = {30.5, 28.0};
    for (int i = 0; i < 12; ++i) low.spheres.push_back({{3.0 * u(rng), 3.0 * u(rng), 205.0 + 0.5 * u(rng)}, 12.0});
    low.hierarchy = blockers::build_sphere_hierarchy(low.spheres);
    for (int meshes = 1; meshes <= 2; ++meshes) {
        blockers::SphereBlockers b;
        b.meshes.push_back(m);
        if (meshes == 2) b.meshes.push_back(low);
        ASSERT_EQ(b.options.sky_culling, blockers::SphereBlockerOptions::SkyCulling::none);
        for (const ts::visibility::ReceiverWindow window :
             {ts::visibility::ReceiverWindow{}, ts::visibility::ReceiverWindow{10, 5, 50, 45}}) {
            ts::visibility::VisibilityRequest req;
            req.horizon.directions = 16;
            req.horizon.window = window;
            req.log_sh = true;
            req.blockers = &b;
            req.keep_terrain_log_sh = true;
            const auto gpu = make_gpu_visibility_backend(*context_, {})->compute(grid, req);
            const auto cpu = ts::visibility::make_cpu_visibility_backend()->compute(grid, req);
            ASSERT_EQ(gpu.log_sh.size(), cpu.log_sh.size());
            ASSERT_EQ(gpu.terrain_log_sh.size(), cpu.terrain_log_sh.size());
            double worst = 0.0, changed = 0.0;
            for (std::size_t k = 0; k < cpu.log_sh.size(); ++k) {
                if (std::isnan(cpu.log_sh[k])) {
                    EXPECT_TRUE(std::isnan(gpu.log_sh[k])) << k;
                    continue;
                }
                worst = std::max(worst, double(std::abs(gpu.log_sh[k] - cpu.log_sh[k])));
                changed = std::max(changed, double(std::abs(cpu.log_sh[k] - cpu.terrain_log_sh[k])));
            }
            EXPECT_GT(changed, 0.05);  // the meshes do shadow the window
            // The terrain's log-SH of the two paths differs by its own GPU/CPU tolerance (the
            // visibility agreement tests); the blockers' part adds float rounding.
            double terrain_worst = 0.0;
            for (std::size_t k = 0; k < cpu.terrain_log_sh.size(); ++k)
                if (!std::isnan(cpu.terrain_log_sh[k]))
                    terrain_worst =
                        std::max(terrain_worst, double(std::abs(gpu.terrain_log_sh[k] - cpu.terrain_log_sh[k])));
            std::printf("%d mesh(es), window %d,%d: log-SH max %.3g apart (terrain alone %.3g), the meshes change it "
                        "by up to %.3g\n",
                        meshes, window.col0, window.row0, worst, terrain_worst, changed);
            EXPECT_LE(worst, terrain_worst + 1e-4 * changed + 1e-6);
            bool on_device = false;
            for (const auto& stage : gpu.stages)
                if (stage.label.rfind("sphere blockers", 0) == 0) on_device = stage.path == context_->device_info().name;
            EXPECT_TRUE(on_device);
        }
    }
}

}  // namespace
}  // namespace ts::gpu::visibility
