#pragma once
// How two sets of transfer vectors ([16][texels], render::transfer_vectors' layout) agree, for
// the GPU tests that compare the device's transfer with the CPU's.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace ts::gpu::test_support {

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
