#include "core/visibility/horizon_sh.hpp"

#include <algorithm>
#include <cmath>

#include "core/sh/sh_exp.hpp"
#include "core/util/parallel_for.hpp"
#include "core/visibility/visibility_products.hpp"

namespace ts::visibility {

namespace {
constexpr int kCoeffs = 16;
}  // namespace

std::vector<float> log_sh_raster(const HorizonSet& set, float log_eps, int threads) {
    ProductRequest r;
    r.svf = r.sky_visible = false;
    r.log_eps = log_eps;
    r.threads = threads;
    std::vector<float> out(set.texels() * kCoeffs);
    visibility_products_into(set, r, {out.data(), nullptr, nullptr});
    return out;
}

std::array<float, 16> level_log_visibility(int directions, float log_eps) {
    HorizonSet level;
    level.width = level.height = 1;
    level.directions = directions;
    level.angle.resize(std::size_t(directions));
    for (int d = 0; d < directions; ++d) level.angle[std::size_t(d)] = 0.0f;
    const std::vector<float> v = log_sh_raster(level, log_eps, 1);
    std::array<float, 16> out{};
    for (int i = 0; i < kCoeffs; ++i) out[std::size_t(i)] = v[std::size_t(i)];
    return out;
}

std::vector<float> exp_sh_raster(std::span<const float> log_sh, std::size_t texels, sh::ExpMethod method,
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
