#pragma once
// How two sets of transfer vectors ([16][texels], render::transfer_vectors' layout) agree, and
// the light both GPU transfer/shading tests feed them, for the tests that compare the device's
// transfer and shading with the CPU's.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

namespace ts::gpu::test_support {

// A sky-like light: a bright constant, brighter towards the zenith and the south-west, some
// detail in the higher bands.
inline std::array<glm::vec3, 16> sky_light() {
    std::array<glm::vec3, 16> l{};
    l[0] = glm::vec3(2.0f, 2.6f, 3.4f);
    l[1] = glm::vec3(-0.3f);
    l[2] = glm::vec3(1.1f, 1.2f, 1.4f);
    l[3] = glm::vec3(-0.4f, -0.3f, -0.2f);
    for (int i = 4; i < 16; ++i) l[std::size_t(i)] = glm::vec3(0.05f * float(i % 5) - 0.1f);
    return l;
}

// Per texel: max |test - ref| over the 16 coefficients, over the reference's norm. Texels beyond
// `tol` are counted as flips and kept out of `worst`; a NaN on one side only is a mismatch.
struct TransferAgreement {
    double worst = 0;
    std::size_t flips = 0, nan_mismatches = 0;
};

inline TransferAgreement compare_transfer(const std::vector<float>& test, const std::vector<float>& ref,
                                          std::size_t texels, double tol) {
    TransferAgreement a;
    for (std::size_t t = 0; t < texels; ++t) {
        double norm = 0, diff = 0;
        bool nan_test = false, nan_ref = false;
        for (std::size_t i = 0; i < 16; ++i) {
            const double r = ref[i * texels + t], x = test[i * texels + t];
            nan_ref = nan_ref || std::isnan(r);
            nan_test = nan_test || std::isnan(x);
            norm += r * r;
            diff = std::max(diff, std::abs(r - x));
        }
        if (nan_ref || nan_test) {
            a.nan_mismatches += nan_ref != nan_test;
            continue;
        }
        const double rel = diff / std::max(std::sqrt(norm), 1e-30);
        if (rel > tol) ++a.flips;
        else a.worst = std::max(a.worst, rel);
    }
    return a;
}

}  // namespace ts::gpu::test_support
