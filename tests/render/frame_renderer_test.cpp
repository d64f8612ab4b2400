#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/render/frame_renderer.hpp"
#include "core/render/render_backend.hpp"
#include "tests/render/frame_stack.hpp"
#include "core/util/angles.hpp"
#include "core/visibility/visibility_backend.hpp"
#include "tests/render/uniform_sky.hpp"

namespace ts::render {
namespace {

using Renderer = testing::FrameStack;

using testing::UniformSky;

struct Terrain {
    int w, h;
    std::vector<float> z;
    terrain::HeightGrid grid;
    Terrain(int w_, int h_, float height) : w(w_), h(h_), z(std::size_t(w_ * h_), height) {
        grid = terrain::HeightGrid::uniform(w, h, z, 30, 30);
    }
    MaterialRaster grey(float albedo) const {
        MaterialRaster m = rule_materials(grid, terrain_normals(grid));
        std::fill(m.albedo_r.begin(), m.albedo_r.end(), albedo);
        std::fill(m.albedo_g.begin(), m.albedo_g.end(), albedo);
        std::fill(m.albedo_b.begin(), m.albedo_b.end(), albedo);
        std::fill(m.ks.begin(), m.ks.end(), 0.0f);
        return m;
    }
};

RendererOptions small_options() {
    RendererOptions o;
    o.directions = 16;
    o.curvature = false;
    o.threads = 2;
    return o;
}

TEST(FrameRenderer, FlatPlaneUnderUniformSkyGivesAlbedoTimesL) {
    Terrain t(16, 16, 500.0f);
    RendererOptions o = small_options();
    o.band_correction = false;  // the raw log-SH pipeline; the corrected one is tested below
    Renderer r(t.grid, t.grey(0.3f), terrain_normals(t.grid), {}, o);
    const SunState sun{180.0, 40.0};
    const UniformSky sky(2.0f, sun_direction(sun), 0.0f);
    std::vector<glm::vec3> out;
    r->render(sky, sun, out);
    ASSERT_EQ(out.size(), 256u);
    // Exact: albedo * E / pi = albedo * L = 0.6. The log-SH pipeline (order-4 SH of the
    // visibility and of the clamped cosine, log floors eps_v = 0.1 and eps_brdf = 0.05,
    // scaling-and-squaring exponentiation) is not exact: it gives 0.970 of the truth on an open
    // plane (hybrid: 0.81, docs/rendering.md). 5% allows that and catches a wrong lobe or axis.
    for (const auto& c : out) {
        EXPECT_NEAR(c.x, 0.6f, 0.6f * 0.05f);
        EXPECT_FLOAT_EQ(c.x, c.y);
    }
    // Every texel of an open plane sees the same sky: the result must not vary across it.
    EXPECT_NEAR(out[0].x, out[135].x, 1e-4f);
}

// With the band correction (the default) an open texel's transfer is the projected clamped
// cosine, so a flat plane under any sky gets albedo * E / pi up to the visibility's lower-hemisphere
// floor and the sky's SH quadrature: 1% here. A sky brighter at the zenith (L = a + b z,
// E / pi = a + 2b/3) checks more than the DC band.
class ZenithSky : public UniformSky {
public:
    ZenithSky(float a, float b, glm::dvec3 sun_dir) : UniformSky(0.0f, sun_dir, 0.0f), a_(a), b_(b) {}
    light::Rgb radiance(const glm::dvec3& d) const override { return light::Rgb(d.z > 0 ? a_ + b_ * float(d.z) : 0.0f); }

private:
    float a_, b_;
};

TEST(FrameRenderer, BandCorrectionMakesAnOpenPlaneExact) {
    Terrain t(16, 16, 500.0f);
    Renderer r(t.grid, t.grey(0.3f), terrain_normals(t.grid), {}, small_options());
    const SunState sun{180.0, 40.0};
    const ZenithSky sky(1.0f, 1.5f, sun_direction(sun));
    std::vector<glm::vec3> out;
    r->render(sky, sun, out);
    const float expected = 0.3f * (1.0f + 2.0f * 1.5f / 3.0f);
    for (const auto& c : out) EXPECT_NEAR(c.x, expected, expected * 0.01f);
}

TEST(FrameRenderer, SunOnAFlatPlaneIsLambertExactly) {
    Terrain t(12, 12, 100.0f);
    Renderer r(t.grid, t.grey(0.25f), terrain_normals(t.grid), {}, small_options());
    const SunState sun{135.0, 30.0};
    const UniformSky sky(0.0f, sun_direction(sun), 100.0f);
    std::vector<glm::vec3> out;
    r->render(sky, sun, out);
    // No sky light; sun fully visible: L = albedo/pi * E * sin(elevation). Only float rounding.
    const float expected = float(0.25 / kPi * 100.0 * 0.5);
    for (std::size_t i = 0; i < out.size(); ++i) {
        EXPECT_NEAR(r->sun_visibility()[i], 1.0f, 1e-6f) << i;
        EXPECT_NEAR(out[i].x, expected, expected * 1e-4f) << i;
    }
}

TEST(FrameRenderer, AWallShadowsTheTexelsBehindIt) {
    // An east-west wall 60 m high on row 10 of a flat plane (30 m texels); the sun from the
    // south at 30 degrees casts a shadow 60 / tan(30) = 104 m = 3.5 texels north of it.
    Terrain t(20, 20, 0.0f);
    for (int c = 0; c < t.w; ++c) t.z[std::size_t(10 * t.w + c)] = 60.0f;
    t.grid = terrain::HeightGrid::uniform(t.w, t.h, t.z, 30, 30);
    MaterialRaster m = t.grey(0.5f);
    std::fill(m.water.begin(), m.water.end(), 0);  // height 0 would be sea: keep it land
    RendererOptions direct = small_options();
    direct.bounce.bounces = 0;  // direct light: nothing at all in the shadow
    Renderer r(t.grid, m, terrain_normals(t.grid), {}, direct);
    const SunState sun{180.0, 30.0};
    const UniformSky sky(0.0f, sun_direction(sun), 100.0f);
    std::vector<glm::vec3> out;
    r->render(sky, sun, out);
    const auto vis = [&](int row) { return r->sun_visibility()[std::size_t(row * t.w + 10)]; };
    EXPECT_NEAR(vis(13), 1.0f, 1e-3f);  // south of the wall: lit
    EXPECT_NEAR(vis(15), 1.0f, 1e-3f);
    EXPECT_NEAR(vis(9), 0.0f, 1e-3f);   // 1..3 texels north (30..90 m < 104 m): shadowed
    EXPECT_NEAR(vis(8), 0.0f, 1e-3f);
    EXPECT_NEAR(vis(7), 0.0f, 1e-3f);
    EXPECT_NEAR(vis(5), 1.0f, 1e-3f);   // 5 texels (150 m) north: lit again
    EXPECT_NEAR(out[std::size_t(8 * t.w + 10)].x, 0.0f, 1e-6f);
    EXPECT_GT(out[std::size_t(5 * t.w + 10)].x, 1.0f);
    // With the default bounce the shadow gets some of the light the sunlit wall reflects.
    Renderer bounced(t.grid, m, terrain_normals(t.grid), {}, small_options());
    std::vector<glm::vec3> with_bounce;
    bounced->render(sky, sun, with_bounce);
    const float shadow = with_bounce[std::size_t(8 * t.w + 10)].x, lit = with_bounce[std::size_t(5 * t.w + 10)].x;
    EXPECT_GT(shadow, 0.0f);
    EXPECT_LT(shadow, 0.15f * lit);
}

TEST(FrameRenderer, SunBelowHorizonGivesSkyOnly) {
    Terrain t(8, 8, 100.0f);
    Renderer r(t.grid, t.grey(0.3f), terrain_normals(t.grid), {}, small_options());
    const SunState sun{90.0, -5.0};
    const UniformSky sky(1.0f, sun_direction(sun), 50.0f);
    std::vector<glm::vec3> out;
    r->render(sky, sun, out);
    for (std::size_t i = 0; i < out.size(); ++i) {
        EXPECT_EQ(r->sun_visibility()[i], 0.0f);
        EXPECT_NEAR(out[i].x, 0.3f, 0.3f * 0.05f);  // the sky alone, as in the uniform-sky test (5%)
    }
}

TEST(FrameRenderer, WaterMirrorsTheSkyWithFresnel) {
    // Sea level: water. Seen from straight above, it reflects the zenith with F(0) = 0.02
    // for n = 1.333, over a body of albedo 0.02 lit by the sky.
    Terrain t(8, 8, 0.0f);
    MaterialRaster m = rule_materials(t.grid, terrain_normals(t.grid));
    ASSERT_EQ(m.water[0], 1);
    Renderer r(t.grid, std::move(m), terrain_normals(t.grid), {}, small_options());
    EXPECT_EQ(r.state->water_index().size(), 64u);
    const SunState sun{180.0, 40.0};
    const UniformSky sky(10.0f, sun_direction(sun), 0.0f);
    std::vector<glm::vec3> out;
    r->render(sky, sun, out);
    const double f0 = std::pow((1.333 - 1) / (1.333 + 1), 2);
    const double expected = f0 * 10.0 + (1 - f0) * kWaterAlbedo * 10.0;
    // Reflection exact (table lookup of a constant); the body's sky term has the 5% above.
    EXPECT_NEAR(out[27].x, expected, 0.05 * (1 - f0) * kWaterAlbedo * 10.0 + 1e-4);
}

// Hills and a sea-level lake on 30 m texels, with the rule's materials: land, water (mirror)
// and snow (Phong) texels, shadows under a 20-degree sun.
struct Hills {
    int w = 40, h = 36;
    std::vector<float> z;
    terrain::HeightGrid grid;
    Hills() : z(std::size_t(w * h)) {
        for (int r = 0; r < h; ++r)
            for (int c = 0; c < w; ++c) {
                const float d = std::hypot(float(c - 28), float(r - 12));
                z[std::size_t(r * w + c)] = c < 6 && r > 25 ? 0.0f : 3300.0f * std::exp(-d * d / 60.0f) + 40.0f * std::sin(0.4f * c) + 60.0f;
            }
        grid = terrain::HeightGrid::uniform(w, h, z, 30, 30);
    }
};

std::vector<glm::vec3> render_hills(const Hills& hills, const RendererOptions& options, const SunState& sun) {
    const NormalField normals = terrain_normals(hills.grid);
    Renderer r(hills.grid, rule_materials(hills.grid, normals), normals, {}, options);
    EXPECT_GT(r.state->water_index().size(), 0u);
    EXPECT_GT(r.state->specular_index().size(), 0u);
    const ZenithSky sky(1.0f, 2.0f, sun_direction(sun));
    std::vector<glm::vec3> out;
    r->render(sky, sun, out);
    return out;
}

// Largest |a - b| / max(|b|, floor): floor = 1e-3 of the frame's mean keeps texels in deep
// shadow (radiance ~0) from turning rounding into a large ratio.
double worst_relative(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
    double mean = 0;
    for (const auto& c : b) mean += (c.x + c.y + c.z) / 3.0;
    const double floor = 1e-3 * mean / double(b.size());
    double worst = 0;
    for (std::size_t t = 0; t < a.size(); ++t)
        for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(double(a[t][k]) - b[t][k]) / std::max(std::abs(double(b[t][k])), floor));
    return worst;
}

// The CPU backend runs the unfused path (shade_transfer over 16 fp32 planes, then sun and
// albedo); the default runs the fused compact one. Same inputs, so: fp32 storage within float
// rounding (1e-5), fp16 (the default) within 1e-3.
TEST(FrameRenderer, CpuBackendMatchesTheFusedPath) {
    const Hills hills;
    const SunState sun{135.0, 20.0};
    RendererOptions o = small_options();
    const std::unique_ptr<RenderBackend> cpu = make_cpu_backend(2);
    o.backend = cpu.get();
    const std::vector<glm::vec3> unfused = render_hills(hills, o, sun);
    o.backend = nullptr;
    const std::vector<glm::vec3> half = render_hills(hills, o, sun);
    o.shading_precision = DiffuseShading::Precision::single;
    const std::vector<glm::vec3> single = render_hills(hills, o, sun);
    ASSERT_EQ(unfused.size(), half.size());
    const double single_err = worst_relative(single, unfused), half_err = worst_relative(half, unfused);
    EXPECT_LE(single_err, 1e-5);
    EXPECT_LE(half_err, 1e-3);
    ::testing::Test::RecordProperty("single_worst_relative", std::to_string(single_err));
    ::testing::Test::RecordProperty("half_worst_relative", std::to_string(half_err));
    // Without the band correction all 16 coefficients are kept: the same agreement.
    o.band_correction = false;
    const std::vector<glm::vec3> single16 = render_hills(hills, o, sun);
    o.backend = cpu.get();
    const std::vector<glm::vec3> unfused16 = render_hills(hills, o, sun);
    EXPECT_LE(worst_relative(single16, unfused16), 1e-5);
}

// A backend is really used: every stage goes through it (a wrapper counts the calls).
class CountingBackend : public RenderBackend {
public:
    explicit CountingBackend(std::unique_ptr<RenderBackend> inner) : inner_(std::move(inner)) {}
    std::string name() const override { return "counting " + inner_->name(); }
    void transfer_vectors(const TransferInputs& in, float* out) override {
        ++transfers;
        inner_->transfer_vectors(in, out);
    }
    std::unique_ptr<ShadeField> keep_transfer(const float* t, std::size_t texels) override {
        ++kept;
        return inner_->keep_transfer(t, texels);
    }
    int transfers = 0, kept = 0;

private:
    std::unique_ptr<RenderBackend> inner_;
};

class CountingVisibility : public visibility::VisibilityBackend {
public:
    std::string name() const override { return "counting cpu"; }
    visibility::VisibilityResult compute(const terrain::HeightGrid& grid,
                                         const visibility::VisibilityRequest& request) override {
        ++computed;
        EXPECT_TRUE(request.log_sh);
        return inner_->compute(grid, request);
    }
    int computed = 0;

private:
    std::unique_ptr<visibility::VisibilityBackend> inner_ = visibility::make_cpu_visibility_backend();
};

TEST(FrameRenderer, BackendRunsTheHeavyStages) {
    const Hills hills;
    for (const auto terrain : {RendererOptions::TerrainTransfer::exact, RendererOptions::TerrainTransfer::log_sh}) {
        CountingBackend backend(make_cpu_backend(1));
        RendererOptions o = small_options();
        o.terrain_transfer = terrain;
        CountingVisibility visibility;
        o.backend = &backend;
        o.visibility = &visibility;
        render_hills(hills, o, {200.0, 35.0});
        EXPECT_EQ(visibility.computed, 1);
        // The specular texels' (snow), and the diffuse one unless it is projected from the
        // horizons (horizon_transfer.hpp, on the CPU).
        EXPECT_EQ(backend.transfers, terrain == RendererOptions::TerrainTransfer::exact ? 1 : 2);
        EXPECT_EQ(backend.kept, 1);  // the diffuse T, for per-frame shading
        EXPECT_EQ(backend.name(), "counting cpu");
    }
}

}  // namespace
}  // namespace ts::render
