// GLSL and C++ evaluate the same core/sh/sh_shared.h. A compute shader evaluates every
// function in float on the Vulkan device (lavapipe on a machine without a GPU); the C++ side
// evaluates the same text in double from the same float inputs. The validation layer is on and must stay silent.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/sh/sh_shared.hpp"
#include "core/util/angles.hpp"
#include "gpu/batch.hpp"
#include "gpu/spirv.hpp"
#include "tests/gpu/validated_context.hpp"

namespace ts::gpu::embedded {
extern const SpirvBlob sh_agreement_comp;  // tests/gpu/shaders/sh_agreement.comp, embedded by CMake
}

namespace ts::gpu::sh_agreement {
namespace {

namespace shared = ts::sh::shared;

// Mirrors struct Case in sh_agreement.comp (std430, 48 bytes).
struct Case {
    float dx, dy, dz;
    float sigma;
    float theta_b;
    float r, dist;
    float phi_k;
    float delta;
    float log_eps;
    float pad0 = 0.0f, pad1 = 0.0f;
};
static_assert(sizeof(Case) == 48);

struct Push {
    std::uint32_t count;
    std::uint32_t results_per_case;
};

// Float carries 24 bits (6e-8 relative per rounding) and every formula is a handful of
// operations and one sin/cos, so GPU and C++ agree to 1e-6 on values of size up to 1. Two
// scalings make that one number fit every output: a value larger than 1 is compared
// relatively (a float cannot hold 8 or more to 1e-6 absolute), and outputs proportional to
// log_eps are compared in units of |log_eps| (the float error of sin(sigma) is multiplied by it).
constexpr double kTolerance = 1e-6;
// GLSL asin is not compared: the Vulkan spec bounds it loosely (llvmpipe is 3.9e-4 rad off
// near |x| = 1), so the shared header gives shaders ts_sphere_log_zh_rd, which needs none.

// The output layout of the shader, in order.
struct Segment {
    const char* function;
    int size;
    bool scales_with_log_eps;
    double tolerance = kTolerance;
};
constexpr std::array kSegments = {
    Segment{"ts_sh_eval", 16, false},
    Segment{"ts_slice_log_coeffs", 4, true},
    Segment{"ts_slice_sh_integrals", 10, true},
    Segment{"ts_sphere_log_zh", 4, true},
    Segment{"ts_zh_rotate", 16, true},  // rotates the slice coefficients
    Segment{"ts_sphere_log_sh", 16, true},
    Segment{"ts_sphere_log_zh_rd", 4, true},
    Segment{"ts_slice_azimuth_weight", 7, false},
    Segment{"ts_hf_add_slice", 16, true},  // basis values plus a log_eps-scaled slice
    Segment{"ts_sh_dot", 1, true},         // basis values dotted with a sphere's log-SH
};
constexpr int kResultsPerCase = [] {
    int total = 0;
    for (const Segment& segment : kSegments) total += segment.size;
    return total;
}();

// The same evaluation as the shader, in double, appended to out.
void evaluate_in_double(const Case& k, std::vector<double>& out) {
    const glm::dvec3 d(k.dx, k.dy, k.dz);
    double y[16];
    shared::ts_sh_eval(d, y);
    out.insert(out.end(), y, y + 16);
    double c[4];
    shared::ts_slice_log_coeffs(k.sigma, k.log_eps, c);
    out.insert(out.end(), c, c + 4);
    double e[10];
    shared::ts_slice_sh_integrals(k.sigma, k.log_eps, e);
    out.insert(out.end(), e, e + 10);
    double zh[4];
    shared::ts_sphere_log_zh(k.theta_b, k.log_eps, zh);
    out.insert(out.end(), zh, zh + 4);
    double rotated[16];
    shared::ts_zh_rotate(c, d, rotated);
    out.insert(out.end(), rotated, rotated + 16);
    double sphere[16];
    shared::ts_sphere_log_sh(k.theta_b, d, k.log_eps, sphere);
    out.insert(out.end(), sphere, sphere + 16);
    double zh_rd[4];
    shared::ts_sphere_log_zh_rd(k.r, k.dist, k.log_eps, zh_rd);
    out.insert(out.end(), zh_rd, zh_rd + 4);
    for (int m = -3; m <= 3; ++m) out.push_back(shared::ts_slice_azimuth_weight(m, k.phi_k, k.delta));
    double f[16];
    std::copy(y, y + 16, f);
    shared::ts_hf_add_slice(k.sigma, k.phi_k, k.delta, k.log_eps, f);
    out.insert(out.end(), f, f + 16);
    out.push_back(shared::ts_sh_dot(y, sphere));
}

// Directions on a Fibonacci spiral (near-uniform on the sphere) plus the axes, where the
// polynomials take their extreme values. sigma sweeps [-90, 90] degrees including both ends;
// theta_b [0, 180] degrees including a receiver inside its sphere; D from 4 to 128 slices.
std::vector<Case> make_cases(float log_eps) {
    std::vector<glm::dvec3> directions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const int spiral = 1000;
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < spiral; ++i) {
        const double z = 1.0 - 2.0 * (i + 0.5) / spiral;
        const double radius = std::sqrt(1.0 - z * z);
        directions.push_back({radius * std::cos(golden * i), radius * std::sin(golden * i), z});
    }
    const int slice_counts[] = {4, 8, 16, 32, 64, 128};
    std::vector<Case> cases;
    const int n = static_cast<int>(directions.size());
    for (int i = 0; i < n; ++i) {
        const double t = n > 1 ? static_cast<double>(i) / (n - 1) : 0.0;  // 0 .. 1, both ends hit
        const int slices = slice_counts[i % std::size(slice_counts)];
        Case k{};
        k.dx = static_cast<float>(directions[i].x);
        k.dy = static_cast<float>(directions[i].y);
        k.dz = static_cast<float>(directions[i].z);
        k.sigma = static_cast<float>((t - 0.5) * kPi);
        k.theta_b = static_cast<float>(t * kPi);
        k.r = static_cast<float>(1.0 + 0.5 * std::sin(7.0 * i));  // d / r from 0.5 to 4: some inside
        k.dist = static_cast<float>(0.5 + 3.5 * t * t);
        k.delta = static_cast<float>(2.0 * kPi / slices);
        k.phi_k = static_cast<float>((i % slices) * 2.0 * kPi / slices);
        k.log_eps = log_eps;
        cases.push_back(k);
    }
    return cases;
}

using ShAgreementTest = test_support::ValidatedTest;

void run_and_compare(const Context& context, float log_eps) {
    const Kernel kernel(context, "sh_agreement.comp", embedded::sh_agreement_comp.words,
                        {.storage_buffers = 2, .push_constant_bytes = sizeof(Push)});
    const std::vector<Case> cases = make_cases(log_eps);
    const auto count = static_cast<std::uint32_t>(cases.size());
    const Buffer input = context.create_buffer(cases.size() * sizeof(Case));
    const Buffer output = context.create_buffer(cases.size() * kResultsPerCase * sizeof(float));
    std::vector<float> gpu_results(cases.size() * kResultsPerCase);

    Batch batch(context);
    batch.upload(input, std::span<const Case>(cases));
    batch.dispatch(kernel, {input, output}, Push{count, static_cast<std::uint32_t>(kResultsPerCase)},
                   groups_for(count, 64));
    batch.download(output, std::span<float>(gpu_results));
    batch.submit_and_wait();

    std::vector<double> cpu_results;
    for (const Case& k : cases) evaluate_in_double(k, cpu_results);
    ASSERT_EQ(cpu_results.size(), gpu_results.size());

    // Worst scaled difference per function (see kTolerance), reported and checked one by one.
    struct Worst {
        double error = 0.0;
        std::size_t case_index = 0;
        int component = 0;
        double gpu = 0.0, cpu = 0.0;
    };
    std::array<Worst, kSegments.size()> worst{};
    for (std::size_t c = 0; c < cases.size(); ++c) {
        int offset = 0;
        for (std::size_t s = 0; s < kSegments.size(); ++s) {
            for (int j = 0; j < kSegments[s].size; ++j, ++offset) {
                const std::size_t at = c * kResultsPerCase + offset;
                const double unit = kSegments[s].scales_with_log_eps ? std::max(1.0, std::abs(double(log_eps))) : 1.0;
                const double error = std::abs(gpu_results[at] - cpu_results[at]) / std::max(unit, std::abs(cpu_results[at]));
                if (error > worst[s].error) worst[s] = {error, c, j, gpu_results[at], cpu_results[at]};
            }
        }
    }
    for (std::size_t s = 0; s < kSegments.size(); ++s) {
        const Worst& w = worst[s];
        const Case& k = cases[w.case_index];
        std::printf("log_eps %-8.4g %-24s worst scaled |GPU - C++| = %.2e (tolerance %.0e)\n", log_eps,
                    kSegments[s].function, w.error, kSegments[s].tolerance);
        EXPECT_LE(w.error, kSegments[s].tolerance) << kSegments[s].function << "[" << w.component << "] case " << w.case_index
                                       << " (sigma " << k.sigma << ", theta_b " << k.theta_b << ", r " << k.r
                                       << ", dist " << k.dist << ", phi_k " << k.phi_k << ", delta " << k.delta
                                       << "): GPU " << w.gpu << ", C++ " << w.cpu;
    }
}

TEST_F(ShAgreementTest, UnitLogEpsilon) { run_and_compare(*context_, -1.0f); }

TEST_F(ShAgreementTest, RealisticLogEpsilon) {
    run_and_compare(*context_, static_cast<float>(std::log(1e-4)));  // a deep shadow: values up to ~30
}

}  // namespace
}  // namespace ts::gpu::sh_agreement
