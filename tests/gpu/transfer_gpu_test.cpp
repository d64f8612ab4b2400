// The transfer stage on the GPU (gpu/render) against the CPU path (core/render/transfer.hpp) on
// real log-SH visibility of shared DEM crops, with the validation layer on.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/dem/read_dem.hpp"
#include "core/render/transfer.hpp"
#include "core/material/log_brdf.hpp"
#include "core/util/error.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/horizon_sh.hpp"
#include "core/visibility/visibility_grid.hpp"
#include "gpu/batch.hpp"
#include "gpu/render/gpu_transfer.hpp"
#include "gpu/render/shade_recording.hpp"
#include "tests/gpu/transfer_agreement.hpp"
#include "tests/gpu/validated_context.hpp"

namespace ts::gpu::transfer_agreement {
namespace {

namespace vis = ts::visibility;
namespace cr = ts::render;      // the CPU path
namespace gr = ts::gpu::render;  // the GPU path

// Per texel of a centred crop: the CPU's log-SH visibility (exact horizons, 32 azimuths), the
// surface normal, the mirror direction of a view from straight above, and per-texel Phong lobes.
struct Scene {
    std::size_t texels = 0;
    std::vector<float> log_vis;      // [16][texels]
    std::vector<float> normal;       // [texels][3]
    std::vector<float> mirror;       // [texels][3]
    std::vector<float> diffuse_zh;   // [4]
    std::vector<float> phong_zh;     // [texels][4]
};

Scene scene_of(const char* file, int size) {
    const dem::Dem dem = dem::read_dem(std::filesystem::path(TS_SHARED_DATA) / "dem" / file);
    const vis::VisibilityGrid full(dem);
    const terrain::HeightGrid& whole = full.view();
    // The centred crop as a grid of its own (horizons see only the crop: quick, and just as
    // real a log-SH field).
    const int w = std::min(size, whole.width), h = std::min(size, whole.height);
    const int c0 = (whole.width - w) / 2, r0 = (whole.height - h) / 2;
    std::vector<float> z(std::size_t(w) * std::size_t(h));
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r) * std::size_t(w) + std::size_t(c)] = whole.at(c0 + c, r0 + r);
    terrain::HeightGrid g;
    g.width = w;
    g.height = h;
    g.z = z;
    g.dx_m.assign(whole.dx_m.begin() + r0, whole.dx_m.begin() + r0 + h);
    g.dy_m.assign(whole.dy_m.begin() + r0, whole.dy_m.begin() + r0 + h);
    vis::HorizonOptions options;
    options.method = vis::HorizonMethod::exact;
    options.directions = 32;
    const vis::HorizonSet horizons = vis::compute_horizons(g, options);

    Scene s;
    s.texels = std::size_t(w) * std::size_t(h);
    s.log_vis = vis::log_sh_raster(horizons);
    s.normal.resize(3 * s.texels);
    s.mirror.resize(3 * s.texels);
    s.phong_zh.resize(4 * s.texels);
    const sh::LogBrdfTable table;
    for (int l = 0; l < 4; ++l) s.diffuse_zh.push_back(float(table.diffuse()[std::size_t(l)]));
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            const int gc = c, gr = r;
            const int cl = std::max(gc - 1, 0), cr = std::min(gc + 1, g.width - 1);
            const int ru = std::max(gr - 1, 0), rd = std::min(gr + 1, g.height - 1);
            // ENU: x east (columns), y north (row 0 is north).
            const double dzdx = (g.at(cr, gr) - g.at(cl, gr)) / ((cr - cl) * g.dx_m[std::size_t(gr)]);
            const double dzdy = (g.at(gc, ru) - g.at(gc, rd)) / ((rd - ru) * g.dy_m[std::size_t(gr)]);
            glm::dvec3 n = glm::normalize(glm::dvec3(-dzdx, -dzdy, 1.0));
            if (!std::isfinite(n.x) || !std::isfinite(n.y)) n = {0, 0, 1};
            const glm::dvec3 m = 2.0 * n.z * n - glm::dvec3(0, 0, 1);  // mirror of the view up
            const std::size_t t = std::size_t(r) * std::size_t(w) + std::size_t(c);
            for (int k = 0; k < 3; ++k) {
                s.normal[3 * t + std::size_t(k)] = float(n[k]);
                s.mirror[3 * t + std::size_t(k)] = float(m[k]);
            }
            const sh::ZhVec zh = table.phong(1.0 + double(t % 97) * 2.0);  // exponents 1..193
            for (int l = 0; l < 4; ++l) s.phong_zh[4 * t + std::size_t(l)] = float(zh[std::size_t(l)]);
        }
    return s;
}

cr::TransferInputs diffuse_inputs(const Scene& s) {
    cr::TransferInputs in;
    in.texels = s.texels;
    in.log_visibility = s.log_vis.data();
    in.lobe_axis = s.normal.data();
    in.lobe_log_zh = s.diffuse_zh.data();
    in.uniform_lobe = true;
    return in;
}

cr::TransferInputs phong_inputs(const Scene& s) {
    cr::TransferInputs in;
    in.texels = s.texels;
    in.log_visibility = s.log_vis.data();
    in.lobe_axis = s.mirror.data();
    in.lobe_log_zh = s.phong_zh.data();
    return in;
}


// Tolerances. Both sides run the same float exponentiation (core/sh/sh_exp_shared.h); they
// differ in the lobe's rotation (double on the CPU, float on the GPU: ~1e-7 of the log), in the
// order llvmpipe fuses multiply-adds, and in exp/log (llvmpipe within a few ulp). The
// squarings amplify that by up to 2^k: measured 2e-6 of a texel's norm at worst. Bound 1e-4
// of the texel's norm (the target).
// The hybrid method chooses its number of squarings k by comparing the non-DC magnitude with
// powers of two; a texel whose magnitude lies within rounding (1e-7 relative) of such a
// boundary can be decided the other way, which changes T by the method's own error (~1e-2).
// At most kFlipFraction of the texels may do so (measured: none).
constexpr double kTransferTol = 1e-4;
constexpr double kFlipFraction = 1e-4;
// Shading: the 16-term dot of T, 1e-4 of the sum of the terms' magnitudes (measured 1e-6).
constexpr double kShadeTol = 1e-4;

using test_support::sky_light;
using GpuTransferTest = test_support::ValidatedTest;

TEST_F(GpuTransferTest, AgreesWithTheCpuOnSharedDemCrops) {
    for (const char* file : {"N00E010.hgt", "srtm3_N39E040_1000px.tif"}) {
        const Scene s = scene_of(file, 160);
        for (bool phong : {false, true}) {
            const cr::TransferInputs in = phong ? phong_inputs(s) : diffuse_inputs(s);
            std::vector<float> cpu(16 * s.texels), gpu(16 * s.texels);
            cr::transfer_vectors(in, cpu.data());
            gr::TransferField field(*context_, in);
            field.download(gpu.data());
            const test_support::TransferAgreement a = test_support::compare_transfer(gpu, cpu, s.texels, kTransferTol);
            std::printf("%s %s: T worst %.2e of the norm, flips %zu of %zu\n", file, phong ? "phong" : "diffuse",
                        a.worst, a.flips, s.texels);
            EXPECT_EQ(a.nan_mismatches, 0u) << file;
            EXPECT_LE(double(a.flips), kFlipFraction * double(s.texels)) << file;
            EXPECT_LE(a.worst, kTransferTol) << file;

            // Relight the GPU's T on both sides: only the dot products are compared here.
            const auto light = sky_light();
            std::vector<glm::vec3> rgb_cpu(s.texels), rgb_gpu(s.texels);
            cr::shade_transfer(gpu.data(), s.texels, light, rgb_cpu.data());
            field.shade(light, rgb_gpu.data());
            double worst = 0;
            for (std::size_t t = 0; t < s.texels; ++t)
                for (int c = 0; c < 3; ++c) {
                    if (std::isnan(rgb_cpu[t][c])) {
                        EXPECT_TRUE(std::isnan(rgb_gpu[t][c])) << t;
                        continue;
                    }
                    double mag = 0;
                    for (std::size_t i = 0; i < 16; ++i) mag += std::abs(double(gpu[i * s.texels + t]) * light[i][c]);
                    const double e = std::abs(double(rgb_gpu[t][c]) - double(rgb_cpu[t][c])) / std::max(mag, 1e-30);
                    worst = std::max(worst, e);
                    ASSERT_LE(e, kShadeTol) << file << " " << t;
                }
            std::printf("%s %s: shade worst %.2e of the terms' magnitude\n", file, phong ? "phong" : "diffuse", worst);
        }
    }
}

TEST_F(GpuTransferTest, BandsJoinIntoTheWholeResultAndVoidsStayNan) {
    Scene s = scene_of("N00E010.hgt", 64);
    for (std::size_t i = 0; i < 16; i += 5) s.log_vis[i * s.texels + 100] = std::numeric_limits<float>::quiet_NaN();
    s.mirror[3 * 7 + 2] = std::numeric_limits<float>::quiet_NaN();  // the Phong lobe's axis
    const cr::TransferInputs in = phong_inputs(s);
    std::vector<float> whole(16 * s.texels), banded(16 * s.texels);
    gr::TransferField one(*context_, in);
    one.download(whole.data());
    gr::TransferField bands(*context_, in, 1000);  // 4096 texels: five bands, the last short
    EXPECT_EQ(bands.bands(), 5);
    bands.download(banded.data());
    for (std::size_t k = 0; k < whole.size(); ++k) {
        if (std::isnan(whole[k])) EXPECT_TRUE(std::isnan(banded[k])) << k;
        else ASSERT_EQ(whole[k], banded[k]) << k;
    }
    for (std::size_t i = 0; i < 16; ++i) {
        EXPECT_TRUE(std::isnan(whole[i * s.texels + 100])) << i;
        EXPECT_FALSE(std::isnan(whole[i * s.texels + 101])) << i;
    }
    // Texel 7 has no lobe axis: its lobe, hence T, is NaN too (as on the CPU).
    EXPECT_TRUE(std::isnan(whole[7]));

    std::vector<glm::vec3> rgb_one(s.texels), rgb_bands(s.texels), rgb_shot(s.texels);
    one.shade(sky_light(), rgb_one.data());
    bands.shade(sky_light(), rgb_bands.data());
    gr::shade_transfer(*context_, whole.data(), s.texels, sky_light(), rgb_shot.data());
    for (std::size_t t = 0; t < s.texels; ++t)
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(std::isnan(rgb_one[t][c]), t == 100 || t == 7) << t;
            if (std::isnan(rgb_one[t][c])) continue;
            ASSERT_EQ(rgb_one[t][c], rgb_bands[t][c]) << t;
            ASSERT_EQ(rgb_one[t][c], rgb_shot[t][c]) << t;
        }
}

// Equal as bits (NaN radiance of a void included): the recorded relight runs the one-shot
// path's kernel on the same inputs.
void expect_same_bits(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b, const char* what) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t t = 0; t < a.size(); ++t)
        ASSERT_EQ(std::memcmp(&a[t], &b[t], sizeof(glm::vec3)), 0) << what << " texel " << t;
}

// The per-frame relight is recorded once and re-submitted: frames with changing light, over
// several bands (the last short and padded), on the direct path lavapipe takes and on the
// staging path of a discrete GPU, each give the one-shot shade_transfer's radiance.
TEST_F(GpuTransferTest, RecordedRelightRepeatsTheOneShotResultFrameAfterFrame) {
    Scene s = scene_of("N00E010.hgt", 45);  // 2025 texels
    s.log_vis[3 * s.texels + 11] = std::numeric_limits<float>::quiet_NaN();
    std::vector<float> t(16 * s.texels);
    gr::transfer_vectors(*context_, diffuse_inputs(s), t.data());
    std::array<glm::vec3, 16> dim = sky_light();
    for (glm::vec3& c : dim) c *= -0.5f;
    const std::array<glm::vec3, 16> lights[] = {sky_light(), dim, sky_light()};

    gr::TransferField field(*context_, t.data(), s.texels, 700);  // bands of 700, 700, 625
    ASSERT_EQ(field.bands(), 3);
    // The staging path on the same bands of T, uploaded here.
    const gr::TransferKernels kernels(*context_);
    std::vector<Buffer> planes;
    std::vector<gr::ShadeRecording::BandInput> inputs;
    Batch batch(*context_);
    for (std::size_t first = 0; first < s.texels; first += 700) {
        const std::size_t n = std::min<std::size_t>(700, s.texels - first), stride = gr::padded_to_quads(n);
        planes.push_back(context_->create_buffer(16 * stride * sizeof(float)));
        batch.fill(planes.back());
        for (std::size_t i = 0; i < 16; ++i)
            batch.upload(planes.back(), std::span<const float>(t.data() + i * s.texels + first, n),
                         i * stride * sizeof(float));
        inputs.push_back({first, n, nullptr});
    }
    batch.submit_and_wait();
    for (std::size_t k = 0; k < inputs.size(); ++k) inputs[k].transfer = &planes[k];
    gr::ShadeRecording staging(*context_, kernels.shade(), inputs, gr::ShadeRecording::Readback::staging);
    EXPECT_FALSE(staging.reads_directly());

    for (const auto& light : lights) {
        std::vector<glm::vec3> shot(s.texels), recorded(s.texels), staged(s.texels);
        gr::shade_transfer(*context_, t.data(), s.texels, light, shot.data());
        field.shade(light, recorded.data());
        std::array<float, 64> l4{};
        for (std::size_t i = 0; i < 16; ++i)
            for (int c = 0; c < 3; ++c) l4[4 * i + std::size_t(c)] = light[i][c];
        staging.run(l4, staged.data());
        EXPECT_TRUE(std::isnan(shot[11].x));
        EXPECT_FALSE(std::isnan(shot[12].x));
        expect_same_bits(shot, recorded, "recorded");
        expect_same_bits(shot, staged, "staged");
        bool has_shade_stage = false;
        for (const auto& st : field.stages()) has_shade_stage = has_shade_stage || st.label == "shade";
        EXPECT_TRUE(has_shade_stage);
    }
}

TEST_F(GpuTransferTest, UniformLobeEqualsThePerTexelLobe) {
    const Scene s = scene_of("N00E010.hgt", 48);
    cr::TransferInputs in = diffuse_inputs(s);
    std::vector<float> zh(4 * s.texels);
    for (std::size_t t = 0; t < s.texels; ++t) std::copy(s.diffuse_zh.begin(), s.diffuse_zh.end(), zh.begin() + 4 * t);
    std::vector<float> uniform(16 * s.texels), per_texel(16 * s.texels);
    gr::transfer_vectors(*context_, in, uniform.data());
    in.uniform_lobe = false;
    in.lobe_log_zh = zh.data();
    const auto stages = gr::transfer_vectors(*context_, in, per_texel.data());
    EXPECT_EQ(uniform, per_texel);
    bool has_transfer_stage = false;
    for (const auto& st : stages) has_transfer_stage = has_transfer_stage || st.label == "transfer";
    EXPECT_TRUE(has_transfer_stage);
}

TEST_F(GpuTransferTest, OnlyTheHybridMethodRunsOnTheGpu) {
    const Scene s = scene_of("N00E010.hgt", 8);
    cr::TransferInputs in = diffuse_inputs(s);
    in.method = sh::ExpMethod::taylor;
    EXPECT_THROW(gr::TransferField(*context_, in), InputError);
    in.texels = 0;
    in.method = sh::ExpMethod::hybrid;
    gr::TransferField empty(*context_, in);
    empty.shade(sky_light(), nullptr);
    empty.download(nullptr);
}

}  // namespace
}  // namespace ts::gpu::transfer_agreement
