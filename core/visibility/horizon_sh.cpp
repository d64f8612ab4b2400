#include "core/visibility/horizon_sh.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "core/sh/sh_exp.hpp"
#include "core/sh/slice_projector.hpp"
#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"

namespace ts::visibility {

namespace {
constexpr int kCoeffs = 16;
constexpr int kRowsPerItem = 16;  // work item for the thread pool
}  // namespace

std::vector<float> log_sh_raster(const HorizonSet& set, float log_eps, int threads) {
    if (set.directions < 4)
        throw InputError("--sh: needs at least 4 directions, got " + std::to_string(set.directions));
    const sh::SliceProjector projector(set.directions);
    const std::size_t n = set.texels();
    std::vector<float> out(n * kCoeffs);
    const int items = (set.height + kRowsPerItem - 1) / kRowsPerItem;
    parallel_for(items, thread_count(threads), [&](int item, int) {
        std::vector<float> sigma(std::size_t(set.directions));
        float coeffs[kCoeffs];
        const std::size_t t0 = std::size_t(item) * kRowsPerItem * set.width;
        const std::size_t t1 = std::min(n, t0 + std::size_t(kRowsPerItem) * set.width);
        for (std::size_t t = t0; t < t1; ++t) {
            bool is_void = false;
            for (int d = 0; d < set.directions; ++d) {
                sigma[std::size_t(d)] = set.plane(d)[t];
                is_void |= std::isnan(sigma[std::size_t(d)]);
            }
            if (is_void) {
                for (int i = 0; i < kCoeffs; ++i) out[std::size_t(i) * n + t] = std::numeric_limits<float>::quiet_NaN();
                continue;
            }
            projector.project_horizons(sigma.data(), log_eps, coeffs);
            for (int i = 0; i < kCoeffs; ++i) out[std::size_t(i) * n + t] = coeffs[i];
        }
    });
    return out;
}

std::vector<float> exp_sh_raster(const std::vector<float>& log_sh, std::size_t texels, sh::ExpMethod method,
                                 int threads) {
    std::vector<float> out(log_sh.size());
    const int items = int((texels + 4095) / 4096);
    parallel_for(items, thread_count(threads), [&](int item, int) {
        float in[kCoeffs], res[kCoeffs];
        const std::size_t t1 = std::min(texels, std::size_t(item + 1) * 4096);
        for (std::size_t t = std::size_t(item) * 4096; t < t1; ++t) {
            for (int i = 0; i < kCoeffs; ++i) in[i] = log_sh[std::size_t(i) * texels + t];
            if (std::isnan(in[0])) {
                for (int i = 0; i < kCoeffs; ++i) out[std::size_t(i) * texels + t] = in[0];
                continue;
            }
            sh::sh_exp(method, in, res);
            for (int i = 0; i < kCoeffs; ++i) out[std::size_t(i) * texels + t] = res[i];
        }
    });
    return out;
}

}  // namespace ts::visibility
