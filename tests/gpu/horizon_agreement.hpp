#pragma once
// How two horizon sets agree ([direction][texel] angles in radians), for the GPU tests that
// compare the device's horizons with the CPU's. A texel-azimuth beyond `tol` is a flip (the two
// paths picked different blockers at a near tie): counted, kept out of `max`, and its texel
// marked so per-texel products can be compared on the texels without one.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "core/visibility/horizon_set.hpp"

namespace ts::gpu::test_support {

struct HorizonAgreement {
    double max = 0;  // over texel-azimuths that are not flips
    double rms = 0;  // over all compared texel-azimuths
    std::size_t flips = 0, compared = 0, nan_mismatches = 0;
    std::vector<bool> flipped;  // per texel: some azimuth flipped
};

// `verbose_env`: if that environment variable is set, the first 20 flips are printed.
inline HorizonAgreement compare_horizons(const ts::visibility::HorizonSet& ref, const ts::visibility::HorizonSet& test,
                                         double tol, const char* verbose_env = nullptr) {
    HorizonAgreement c;
    const std::size_t texels = ref.texels();
    const bool verbose = verbose_env && std::getenv(verbose_env);
    c.flipped.assign(texels, false);
    double sum2 = 0;
    const std::size_t n = std::min(ref.angle.size(), test.angle.size());
    for (std::size_t i = 0; i < n; ++i) {
        const float a = ref.angle[i], b = test.angle[i];
        if (std::isnan(a) || std::isnan(b)) {
            c.nan_mismatches += std::isnan(a) != std::isnan(b);
            continue;
        }
        const double d = std::abs(double(a) - double(b));
        sum2 += d * d;
        ++c.compared;
        if (d > tol) {
            if (verbose && c.flips < 20)
                std::printf("  flip d=%zu col=%zu row=%zu ref %.6f test %.6f\n", i / texels,
                            (i % texels) % std::size_t(ref.width), (i % texels) / std::size_t(ref.width), a, b);
            ++c.flips;
            c.flipped[i % texels] = true;
            continue;
        }
        c.max = std::max(c.max, d);
    }
    c.rms = c.compared ? std::sqrt(sum2 / double(c.compared)) : 0.0;
    return c;
}

}  // namespace ts::gpu::test_support
