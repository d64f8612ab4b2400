// Relief contrast stretches the shading (radiance / albedo) about its log-average, not the
// albedo; automatic k reaches the target spread and leaves a contrasty picture alone.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/render/relief_contrast.hpp"

namespace ts::render {
namespace {

MaterialRaster land(std::size_t n, const std::vector<glm::vec3>& albedo) {
    MaterialRaster m;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 a = albedo[i % albedo.size()];
        m.albedo_r.push_back(a.x), m.albedo_g.push_back(a.y), m.albedo_b.push_back(a.z);
        m.ks.push_back(0), m.alpha.push_back(1), m.water.push_back(0), m.surface.push_back(Surface::grassland);
    }
    return m;
}

float lum(const glm::vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

TEST(ReliefContrast, StretchesTheShadingNotTheAlbedo) {
    const std::size_t n = 200;
    // Two albedos (forest-like and field-like) under irradiance from 0.8 to 1.2 (a soft light).
    const MaterialRaster m = land(n, {{0.04f, 0.07f, 0.03f}, {0.13f, 0.125f, 0.075f}});
    std::vector<glm::vec3> radiance(n), irradiance(n);
    for (std::size_t i = 0; i < n; ++i) {
        irradiance[i] = glm::vec3(0.8f + 0.4f * float(i) / float(n - 1));
        radiance[i] = glm::vec3(m.albedo_r[i], m.albedo_g[i], m.albedo_b[i]) * irradiance[i];
    }
    std::vector<glm::vec3> out = radiance;
    const ReliefContrastApplied applied = apply_relief_contrast(out, m, {.automatic = false, .k = 3.0});
    EXPECT_EQ(applied.k, 3.0);
    EXPECT_EQ(applied.albedo_factor, 1.0);  // a k the user chose leaves the colours alone
    double mean = 0;
    for (const auto& e : irradiance) mean += std::log2(lum(e));
    const double ref = std::exp2(mean / double(n));
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 a(m.albedo_r[i], m.albedo_g[i], m.albedo_b[i]);
        const glm::vec3 e = out[i] / a;  // the albedo is kept: what is left is the new shading
        const double want = ref * std::pow(lum(irradiance[i]) / ref, 3.0);
        EXPECT_NEAR(lum(e), want, 1e-5 * want) << i;
        EXPECT_NEAR(e.x / e.y, 1.0, 1e-5);  // white light stays white
    }
}

TEST(ReliefContrast, AutomaticReachesTheTargetSpreadAndLeavesStrongShadingAlone) {
    const std::size_t n = 1000;
    const MaterialRaster m = land(n, {{0.1f, 0.1f, 0.1f}});
    auto shaded = [&](double low, double high) {
        std::vector<glm::vec3> r(n);
        for (std::size_t i = 0; i < n; ++i) r[i] = glm::vec3(0.1f * float(low + (high - low) * double(i) / double(n - 1)));
        return r;
    };
    std::vector<glm::vec3> soft = shaded(0.8, 1.2);  // 5-95% spread ~0.5 stop
    const double k = apply_relief_contrast(soft, m, {}).k;
    EXPECT_GT(k, 2.0);
    EXPECT_LE(k, 4.0);
    std::vector<glm::vec3> strong = shaded(0.05, 1.0);  // shadows: > 4 stops
    const std::vector<glm::vec3> before = strong;
    EXPECT_EQ(apply_relief_contrast(strong, m, {}).k, 1.0);
    EXPECT_EQ(strong, before);
}

// Under a light soft enough for k > 1, the land colours' contrast is compressed by another 1/k
// (compressed_albedo): forest and fields under the same light end up k times closer in stops.
TEST(ReliefContrast, AutomaticSoftLightAlsoCompressesTheLandColours) {
    const std::size_t n = 1000;
    const glm::vec3 forest{0.035f, 0.060f, 0.028f}, fields{0.130f, 0.125f, 0.075f};
    const MaterialRaster m = land(n, {forest, fields});
    std::vector<glm::vec3> r(n);
    for (std::size_t i = 0; i < n; ++i)
        r[i] = glm::vec3(m.albedo_r[i], m.albedo_g[i], m.albedo_b[i]) * (0.8f + 0.4f * float(i) / float(n - 1));
    std::vector<glm::vec3> out = r;
    const ReliefContrastApplied applied = apply_relief_contrast(out, m, {});
    ASSERT_GT(applied.k, 2.0);
    EXPECT_NEAR(applied.albedo_factor, 1.0 / applied.k, 1e-12);
    // Neighbours 0 and 1 see (nearly) the same light: their brightness ratio is the albedos'.
    const double before = std::log2(lum(fields) / lum(forest));
    const double after = std::log2(lum(out[1]) / lum(out[0]));
    EXPECT_NEAR(after, before / applied.k, 0.05 * before);
    std::vector<glm::vec3> kept = r;
    EXPECT_EQ(apply_relief_contrast(kept, m, {.soften_albedo = false}).albedo_factor, 1.0);
}

TEST(ReliefContrast, WaterAndShinySurfacesAreLeftAlone) {
    MaterialRaster m = land(64, {{0.1f, 0.1f, 0.1f}});
    m.water[3] = 1;
    m.ks[5] = 0.05f;
    std::vector<glm::vec3> r(64);
    for (std::size_t i = 0; i < r.size(); ++i) r[i] = glm::vec3(0.1f * (0.8f + 0.4f * float(i) / 63.0f));
    const std::vector<glm::vec3> before = r;
    apply_relief_contrast(r, m, {.automatic = false, .k = 2.0});
    EXPECT_EQ(r[3], before[3]);
    EXPECT_EQ(r[5], before[5]);
    EXPECT_NE(r[0], before[0]);
}

}  // namespace
}  // namespace ts::render
