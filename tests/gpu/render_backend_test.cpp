// The Vulkan RenderBackend (gpu/render/gpu_render_backend.hpp) against the CPU reference backend
// (core/render/render_backend.hpp's make_cpu_backend) on a real DEM crop: every stage, the
// shared scaling-and-squaring text against core/sh, and whole frames of a FrameRenderer. The
// validation layer is on (ValidatedTest): any message fails the test.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <span>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/dem/read_dem.hpp"
#include "core/light/sky.hpp"
#include "core/render/frame_renderer.hpp"
#include "core/material/material.hpp"
#include "core/render/render_backend.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/material/log_brdf.hpp"
#include "core/sh/sh_exp.hpp"
#include "core/sh/sh_exp_squaring_shared.hpp"
#include "core/terrain/grid_crop.hpp"
#include "core/util/error.hpp"
#include "core/visibility/visibility_grid.hpp"
#include "gpu/render/gpu_render_backend.hpp"
#include "gpu/visibility/gpu_visibility_backend.hpp"
#include "tests/gpu/horizon_agreement.hpp"
#include "tests/render/frame_stack.hpp"
#include "tests/gpu/transfer_agreement.hpp"
#include "tests/gpu/validated_context.hpp"

namespace ts::gpu::render_backend_agreement {
namespace {

namespace vis = ts::visibility;
namespace cr = ts::render;

// Tolerances (measured figures are printed by each test).
// Horizons and log-SH: as tests/gpu/visibility_agreement_test.cpp (the same GPU sweep): a
// texel-azimuth within 1e-4 rad except at most 1e-4 of them ("flips", a float/double decision
// at a discontinuity of the method); log-SH within 1e-4 absolute on texels without a flip.
constexpr double kHorizonTol = 1e-4;
constexpr double kFlipFraction = 1e-4;
constexpr double kLogShTol = 1e-4;
// Transfer: both sides run the same float text (sh_exp_shared.h, sh_exp_squaring_shared.h);
// the lobe rotation (double on the CPU, float on the GPU), fused multiply-adds and llvmpipe's
// exp/log differ by rounding, which up to 24 squarings amplify: 1e-4 of the texel's norm, except
// at most kFlipFraction of texels whose magnitude sits on a halving boundary (k decided the other way).
constexpr double kTransferTol = 1e-4;
// The shared C++ scaling-and-squaring against core/sh's exp_scaling_squaring: the same steps,
// products summed in another order (and k by halving instead of log2): 1e-4 of the norm.
constexpr double kSharedVsCoreTol = 1e-4;
// Shading: a 16-term dot product in float, 1e-5 of the sum of the terms' magnitudes.
constexpr double kShadeTol = 1e-5;
// Whole frames: GPU backend vs the CPU backend, both fp32 T: 1e-4 relative per channel (the
// transfer tolerance carried through). Against the default CPU path (fused, T in fp16):
// its own stated 1e-3 per term, plus the transfer's; relative to the sum, which the terms'
// cancellation makes smaller than their magnitudes: the physical sky's dome has more in bands
// 2-3 than Preetham's (measured 1.2e-3 with the sun 25 degrees up, 3.0e-3 at 8; Preetham's
// 2e-3 at most).
constexpr double kFrameTol = 1e-4;
constexpr double kFrameVsFusedTol = 4e-3;

// A centred 96 x 96 window of the Grenoble DEM (Alps: deep horizons) as a grid of its own.
const terrain::GridCrop& grenoble_crop() {
    static const terrain::GridCrop crop = [] {
        const dem::Dem dem =
            dem::read_dem(std::filesystem::path(TS_SHARED_DATA) / "dem" / "copernicus_N45E005_grenoble_500px.tif");
        const vis::VisibilityGrid full(dem);
        return terrain::centre_crop(full.view(), 96, 96);
    }();
    return crop;
}

vis::HorizonOptions horizon_options() {
    vis::HorizonOptions o;
    o.method = vis::HorizonMethod::exact;
    o.directions = 32;
    return o;
}

// The CPU's horizons and log-SH of the crop, computed once for the whole file.
vis::VisibilityRequest log_sh_request(const vis::HorizonOptions& horizon) {
    vis::VisibilityRequest r;
    r.horizon = horizon;
    r.log_sh = true;
    return r;
}
const vis::VisibilityResult& cpu_visibility() {
    static const vis::VisibilityResult v =
        vis::make_cpu_visibility_backend()->compute(grenoble_crop().grid, log_sh_request(horizon_options()));
    return v;
}

// Transfer inputs on the crop: the diffuse lobe about the normals (one ZH) or Phong lobes of
// exponents 1..193 about the mirror of a view from above (a ZH per texel).
struct Lobes {
    std::vector<float> normal, mirror, diffuse_zh, phong_zh;
};
Lobes lobes_of(const terrain::HeightGrid& g) {
    const cr::NormalField n = cr::terrain_normals(g);
    const std::size_t texels = std::size_t(g.width) * std::size_t(g.height);
    const sh::LogBrdfTable table;
    Lobes l;
    for (int i = 0; i < 4; ++i) l.diffuse_zh.push_back(float(table.diffuse()[std::size_t(i)]));
    for (std::size_t t = 0; t < texels; ++t) {
        const glm::vec3 nrm(n.x[t], n.y[t], n.z[t]);
        const glm::vec3 m = glm::normalize(2.0f * nrm.z * nrm - glm::vec3(0, 0, 1));
        for (int k = 0; k < 3; ++k) l.normal.push_back(nrm[k]), l.mirror.push_back(m[k]);
        const sh::ZhVec zh = table.phong(1.0 + double(t % 97) * 2.0);
        for (int i = 0; i < 4; ++i) l.phong_zh.push_back(float(zh[std::size_t(i)]));
    }
    return l;
}

cr::TransferInputs transfer_inputs(const Lobes& l, std::span<const float> log_sh, bool phong, sh::ExpMethod m) {
    cr::TransferInputs in;
    in.texels = l.normal.size() / 3;
    in.log_visibility = log_sh.data();
    in.lobe_axis = phong ? l.mirror.data() : l.normal.data();
    in.lobe_log_zh = phong ? l.phong_zh.data() : l.diffuse_zh.data();
    in.uniform_lobe = !phong;
    in.method = m;
    return in;
}

using test_support::compare_transfer;
using test_support::sky_light;
using test_support::TransferAgreement;


using GpuRenderBackendTest = test_support::ValidatedTest;

TEST_F(GpuRenderBackendTest, HorizonsAndLogShMatchTheCpuBackend) {
    const terrain::GridCrop& c = grenoble_crop();
    const vis::VisibilityResult& cpu = cpu_visibility();
    const auto gpu_backend = gpu::visibility::make_gpu_visibility_backend(*context_);
    EXPECT_EQ(gpu_backend->name(), context_->device_info().name);
    const vis::VisibilityResult r = gpu_backend->compute(c.grid, log_sh_request(horizon_options()));
    EXPECT_EQ(r.path(), context_->device_info().name);
    EXPECT_TRUE(r.svf.empty());
    const vis::HorizonSet& h = r.horizons;
    const auto& log_sh = r.log_sh;
    ASSERT_EQ(h.angle.size(), cpu.horizons.angle.size());
    ASSERT_EQ(log_sh.size(), cpu.log_sh.size());
    const std::size_t texels = cpu.horizons.texels();
    const test_support::HorizonAgreement ha = test_support::compare_horizons(cpu.horizons, h, kHorizonTol);
    const std::vector<bool>& flipped = ha.flipped;
    const std::size_t flips = ha.flips;
    std::size_t nan_mismatches = ha.nan_mismatches;
    const double worst_h = ha.max;
    double worst_sh = 0;
    for (std::size_t t = 0; t < texels; ++t) {
        if (flipped[t]) continue;
        for (std::size_t i = 0; i < 16; ++i) {
            const float a = cpu.log_sh[i * texels + t], b = log_sh[i * texels + t];
            if (std::isnan(a) || std::isnan(b)) nan_mismatches += std::isnan(a) != std::isnan(b);
            else worst_sh = std::max(worst_sh, std::abs(double(a) - double(b)));
        }
    }
    std::printf("grenoble %dx%d D=32: horizons worst %.2e rad, flips %zu of %zu; log-SH worst %.2e\n", c.grid.width,
                c.grid.height, worst_h, flips, h.angle.size(), worst_sh);
    EXPECT_EQ(nan_mismatches, 0u);
    EXPECT_LE(worst_h, kHorizonTol);
    EXPECT_LE(double(flips), kFlipFraction * double(h.angle.size()));
    EXPECT_LE(worst_sh, kLogShTol);

    // What the device does not run is computed on the CPU, and the stages say so.
    vis::HorizonOptions raymarch = horizon_options();
    raymarch.method = vis::HorizonMethod::raymarch;
    raymarch.directions = 4;
    vis::VisibilityRequest constant = log_sh_request(horizon_options());
    constant.svf = true;
    constant.wedges = vis::WedgeRule::constant;
    const vis::VisibilityResult rm = gpu_backend->compute(c.grid, log_sh_request(raymarch));
    EXPECT_EQ(rm.path(), "cpu");
    const vis::VisibilityResult cw = gpu_backend->compute(c.grid, constant);
    ASSERT_EQ(cw.stages.size(), 2u);
    EXPECT_EQ(cw.stages[0].path, context_->device_info().name);
    EXPECT_EQ(cw.stages[1].path, "cpu");
    EXPECT_EQ(cw.svf.size(), cw.horizons.texels());
}

TEST_F(GpuRenderBackendTest, TransferVectorsMatchTheCpuBackendForHybridAndScalingSquaring) {
    const terrain::GridCrop& c = grenoble_crop();
    const vis::VisibilityResult& cpu = cpu_visibility();
    const Lobes lobes = lobes_of(c.grid);
    const auto gpu_backend = render::make_gpu_backend(*context_);
    const auto cpu_backend = cr::make_cpu_backend();
    for (sh::ExpMethod method : {sh::ExpMethod::hybrid, sh::ExpMethod::scaling_squaring})
        for (bool phong : {false, true}) {
            SCOPED_TRACE(std::string(sh::to_string(method)) + (phong ? " phong" : " diffuse"));
            const cr::TransferInputs in = transfer_inputs(lobes, cpu.log_sh, phong, method);
            std::vector<float> t_cpu(16 * in.texels), t_gpu(16 * in.texels);
            cpu_backend->transfer_vectors(in, t_cpu.data());
            gpu_backend->transfer_vectors(in, t_gpu.data());
            const TransferAgreement a = compare_transfer(t_gpu, t_cpu, in.texels, kTransferTol);
            std::printf("transfer %-16s %-7s: GPU vs CPU worst %.2e of the norm, flips %zu of %zu\n",
                        std::string(sh::to_string(method)).c_str(), phong ? "phong" : "diffuse", a.worst, a.flips,
                        in.texels);
            EXPECT_EQ(a.nan_mismatches, 0u);
            EXPECT_LE(a.worst, kTransferTol);
            EXPECT_LE(double(a.flips), kFlipFraction * double(in.texels));
        }
    cr::TransferInputs in = transfer_inputs(lobes, cpu.log_sh, false, sh::ExpMethod::taylor);
    std::vector<float> out(16 * in.texels);
    EXPECT_THROW(gpu_backend->transfer_vectors(in, out.data()), InputError);
}

TEST_F(GpuRenderBackendTest, SharedScalingSquaringEqualsCoreShWithinRounding) {
    // The shared text (which both the CPU transfer and the shader run) against sh_exp.cpp's
    // exp_scaling_squaring, on the crop's real exponents: V alone and V + the diffuse lobe
    // about the zenith (its ZH at the m = 0 entries).
    const vis::VisibilityResult& cpu = cpu_visibility();
    const Lobes lobes = lobes_of(grenoble_crop().grid);
    const std::size_t texels = cpu.horizons.texels();
    const sh::ExpOptions o;
    double worst = 0;
    for (bool with_lobe : {false, true})
        for (std::size_t t = 0; t < texels; t += 7) {
            float f[16], zero[16] = {}, shared_t[16], core_t[16];
            for (std::size_t i = 0; i < 16; ++i) f[i] = cpu.log_sh[i * texels + t];
            if (with_lobe)
                for (int l = 0; l < 4; ++l) f[l * l + l] += lobes.diffuse_zh[std::size_t(l)];
            sh::exp_shared::ts_transfer_vector_by(TS_TRANSFER_EXP_SCALING_SQUARING, f, zero, o.hybrid_threshold,
                                                  o.squaring_base_order, o.squaring_threshold, o.max_squarings,
                                                  shared_t);
            sh::exp_scaling_squaring(f, core_t, o.squaring_base_order, o.squaring_threshold, o.max_squarings);
            double norm = 0, diff = 0;
            for (int i = 0; i < 16; ++i) {
                norm += double(core_t[i]) * core_t[i];
                diff = std::max(diff, std::abs(double(core_t[i]) - double(shared_t[i])));
            }
            const double rel = diff / std::max(std::sqrt(norm), 1e-30);
            worst = std::max(worst, rel);
            ASSERT_LE(rel, kSharedVsCoreTol) << t;
        }
    std::printf("shared scaling_squaring vs core/sh exp_scaling_squaring: worst %.2e of the norm\n", worst);
    // Non-finite input gives zeros; a NaN in the exponent (a void texel) gives a NaN transfer.
    float bad[16] = {}, zero[16] = {}, out[16];
    bad[3] = INFINITY;
    sh::exp_shared::ts_sh_exp_scaling_squaring(bad, 3, 1.0f, 24, out);
    for (float x : out) EXPECT_EQ(x, 0.0f);
    bad[3] = NAN;
    sh::exp_shared::ts_transfer_vector_by(TS_TRANSFER_EXP_SCALING_SQUARING, bad, zero, 1.0f, 3, 1.0f, 24, out);
    for (float x : out) EXPECT_TRUE(std::isnan(x));
}

TEST_F(GpuRenderBackendTest, KeptTransferShadesAsTheCpuBackendAndBandsJoin) {
    const terrain::GridCrop& c = grenoble_crop();
    const vis::VisibilityResult& cpu = cpu_visibility();
    const Lobes lobes = lobes_of(c.grid);
    cr::TransferInputs in = transfer_inputs(lobes, cpu.log_sh, false, sh::ExpMethod::scaling_squaring);
    std::vector<float> t(16 * in.texels);
    cr::transfer_vectors(in, t.data());
    t[5] = NAN;  // a void texel shades to NaN on both sides
    const auto gpu_backend = render::make_gpu_backend(*context_);
    const auto banded_backend = render::make_gpu_backend(*context_, {.max_band_texels = 1000});  // 10 bands
    const auto cpu_backend = cr::make_cpu_backend();
    const auto gpu_field = gpu_backend->keep_transfer(t.data(), in.texels);
    const auto banded_field = banded_backend->keep_transfer(t.data(), in.texels);
    const auto cpu_field = cpu_backend->keep_transfer(t.data(), in.texels);
    EXPECT_EQ(gpu_field->texels(), in.texels);
    const auto light = sky_light();
    std::vector<glm::vec3> rgb_gpu(in.texels), rgb_banded(in.texels), rgb_cpu(in.texels);
    for (int frame = 0; frame < 2; ++frame) {  // the kept T shades any number of frames
        std::array<glm::vec3, 16> l = light;
        l[0] *= float(1 + frame);
        gpu_field->shade(l, rgb_gpu.data());
        banded_field->shade(l, rgb_banded.data());
        cpu_field->shade(l, rgb_cpu.data());
        double worst = 0;
        for (std::size_t x = 0; x < in.texels; ++x)
            for (int ch = 0; ch < 3; ++ch) {
                if (std::isnan(rgb_cpu[x][ch]) || std::isnan(rgb_gpu[x][ch])) {
                    ASSERT_TRUE(std::isnan(rgb_cpu[x][ch]) && std::isnan(rgb_gpu[x][ch])) << x;
                    ASSERT_TRUE(std::isnan(rgb_banded[x][ch])) << x;
                    continue;
                }
                ASSERT_EQ(rgb_gpu[x][ch], rgb_banded[x][ch]) << x;
                double mag = 0;
                for (std::size_t i = 0; i < 16; ++i) mag += std::abs(double(t[i * in.texels + x]) * l[i][ch]);
                const double e = std::abs(double(rgb_gpu[x][ch]) - double(rgb_cpu[x][ch])) / std::max(mag, 1e-30);
                worst = std::max(worst, e);
                ASSERT_LE(e, kShadeTol) << x;
            }
        std::printf("shade frame %d: GPU vs CPU worst %.2e of the terms' magnitude\n", frame, worst);
    }
    EXPECT_TRUE(std::isnan(rgb_gpu[5].x));
}

// A moving mesh's rectangle rewrite (ShadeField::update_rect): the GPU field, in one band and in
// bands of 1000 texels (the rectangle straddles them), shades as the CPU field rewritten alike.
TEST_F(GpuRenderBackendTest, ARectangleRewriteShadesAsTheCpuFieldAcrossBands) {
    const terrain::GridCrop& c = grenoble_crop();
    const vis::VisibilityResult& cpu = cpu_visibility();
    const Lobes lobes = lobes_of(c.grid);
    cr::TransferInputs in = transfer_inputs(lobes, cpu.log_sh, false, sh::ExpMethod::scaling_squaring);
    std::vector<float> t(16 * in.texels);
    cr::transfer_vectors(in, t.data());
    const auto gpu_backend = render::make_gpu_backend(*context_);
    const auto banded_backend = render::make_gpu_backend(*context_, {.max_band_texels = 1000});
    const auto cpu_backend = cr::make_cpu_backend();
    const auto gpu_field = gpu_backend->keep_transfer(t.data(), in.texels);
    const auto banded_field = banded_backend->keep_transfer(t.data(), in.texels);
    const auto cpu_field = cpu_backend->keep_transfer(t.data(), in.texels);
    const int w = c.grid.width, rw = std::min(17, w - 3), rh = std::min(23, c.grid.height - 5);
    std::vector<float> rect(16 * std::size_t(rw) * std::size_t(rh));
    for (std::size_t k = 0; k < rect.size(); ++k) rect[k] = 0.01f * float(k % 97) - 0.3f;
    for (const auto* f : {&gpu_field, &banded_field, &cpu_field}) (*f)->update_rect(w, 3, 5, rw, rh, rect.data());
    const auto light = sky_light();
    std::vector<glm::vec3> rgb_gpu(in.texels), rgb_banded(in.texels), rgb_cpu(in.texels);
    gpu_field->shade(light, rgb_gpu.data());
    banded_field->shade(light, rgb_banded.data());
    cpu_field->shade(light, rgb_cpu.data());
    long long inside = 0;
    for (std::size_t x = 0; x < in.texels; ++x) {
        const int col = int(x % std::size_t(w)), row = int(x / std::size_t(w));
        inside += col >= 3 && col < 3 + rw && row >= 5 && row < 5 + rh;
        for (int ch = 0; ch < 3; ++ch) {
            if (std::isnan(rgb_cpu[x][ch])) continue;
            ASSERT_EQ(rgb_gpu[x][ch], rgb_banded[x][ch]) << x;
            ASSERT_NEAR(rgb_gpu[x][ch], rgb_cpu[x][ch], 1e-4 * (1 + std::abs(rgb_cpu[x][ch]))) << x;
        }
    }
    EXPECT_EQ(inside, (long long)rw * rh);
    // The rectangle's first texel (3, 5) shades with the rewritten coefficients.
    const std::size_t n = std::size_t(rw) * std::size_t(rh);
    glm::vec3 expected(0.0f);
    for (std::size_t i = 0; i < 16; ++i) expected += rect[i * n] * light[i];
    EXPECT_NEAR(rgb_gpu[std::size_t(5) * std::size_t(w) + 3].x, expected.x, 1e-4 * (1 + std::abs(expected.x)));
    EXPECT_THROW(cpu_field->update_rect(w, w - 2, 0, 5, 1, rect.data()), std::invalid_argument);
}

// A FrameRenderer on the crop with each backend; radiance of two frames compared. The GPU
// backend in small bands (visibility rows and transfer texels) gives the unbanded frames bit
// for bit.
TEST_F(GpuRenderBackendTest, FramesMatchTheCpuPaths) {
    const terrain::GridCrop& c = grenoble_crop();
    const cr::NormalField normals = cr::terrain_normals(c.grid);
    const cr::MaterialRaster materials = cr::rule_materials(c.grid, normals, cr::MaterialRule{});
    const auto gpu_backend = render::make_gpu_backend(*context_);
    const auto banded_backend = render::make_gpu_backend(*context_, {.max_band_texels = 2000});
    const auto gpu_visibility = gpu::visibility::make_gpu_visibility_backend(*context_);
    const auto banded_visibility = gpu::visibility::make_gpu_visibility_backend(*context_, {.max_band_rows = 20});
    const auto cpu_backend = cr::make_cpu_backend();
    cr::RendererOptions o;  // the defaults: scaling_squaring, band correction
    auto make = [&](cr::RenderBackend* b, vis::VisibilityBackend* v) {
        cr::RendererOptions ob = o;
        ob.backend = b;
        ob.visibility = v;
        return std::make_unique<cr::testing::FrameStack>(c.grid, materials, normals, cr::ViewDirections{}, ob);
    };
    const auto on_gpu = make(gpu_backend.get(), gpu_visibility.get());
    const auto on_gpu_banded = make(banded_backend.get(), banded_visibility.get());
    const auto on_cpu_backend = make(cpu_backend.get(), nullptr);
    const auto on_cpu_fused = make(nullptr, nullptr);
    for (const cr::SunState sun : {cr::SunState{135.0, 25.0}, cr::SunState{250.0, 8.0}}) {
        const auto sky = light::make_sky(light::SkyOptions{}, cr::sun_direction(sun));
        std::vector<glm::vec3> g, gb, b, f;
        (*on_gpu)->render(*sky, sun, g);
        (*on_gpu_banded)->render(*sky, sun, gb);
        (*on_cpu_backend)->render(*sky, sun, b);
        (*on_cpu_fused)->render(*sky, sun, f);
        ASSERT_EQ(g.size(), c.grid.z.size());
        double worst_b = 0, worst_f = 0;
        for (std::size_t t = 0; t < g.size(); ++t)
            for (int ch = 0; ch < 3; ++ch) {
                ASSERT_EQ(std::isnan(g[t][ch]), std::isnan(b[t][ch])) << t;
                if (std::isnan(g[t][ch])) continue;
                ASSERT_EQ(g[t][ch], gb[t][ch]) << t;
                const double ref = std::max(std::abs(double(b[t][ch])), 1e-6);
                worst_b = std::max(worst_b, std::abs(double(g[t][ch]) - b[t][ch]) / ref);
                worst_f = std::max(worst_f, std::abs(double(g[t][ch]) - f[t][ch]) / ref);
            }
        std::printf("frame sun %.0f/%.0f deg: GPU vs CPU backend worst rel %.2e, vs CPU fused (fp16) %.2e\n",
                    sun.azimuth_deg, sun.elevation_deg, worst_b, worst_f);
        EXPECT_LE(worst_b, kFrameTol);
        EXPECT_LE(worst_f, kFrameVsFusedTol);
    }
}

}  // namespace
}  // namespace ts::gpu::render_backend_agreement
