#include "core/visibility/sky_integrals.hpp"

#include <cmath>
#include <limits>

#include "core/util/parallel_for.hpp"
#include "core/visibility/sky_shared.hpp"
#include "core/visibility/visibility_products.hpp"

namespace ts::visibility {

namespace {

template <class Wedge>
double integrate(const float* h, int directions, std::size_t stride, WedgeRule rule, Wedge wedge) {
    double sum = 0;
    for (int d = 0; d < directions; ++d) {
        const double a = h[std::size_t(d) * stride];
        if (std::isnan(a)) return std::numeric_limits<double>::quiet_NaN();
        const double b = rule == WedgeRule::linear ? double(h[std::size_t((d + 1) % directions) * stride]) : a;
        sum += wedge(a, b);
    }
    return sum / directions;
}

template <class PerTexel>
std::vector<float> raster(const HorizonSet& set, int threads, PerTexel per_texel) {
    std::vector<float> out(set.texels());
    parallel_for(set.height, thread_count(threads), [&](int row, int) {
        for (int col = 0; col < set.width; ++col) {
            const std::size_t i = std::size_t(row) * set.width + col;
            out[i] = float(per_texel(set.angle.data() + i, set.directions, set.texels()));
        }
    });
    return out;
}

}  // namespace

// The formulas live in sky_shared.h, shared with the GPU's vis_sky.comp.
double wedge_mean_cos2(double a, double b) { return shared::ts_wedge_mean_cos2(a, b); }
double wedge_mean_sin(double a, double b) { return shared::ts_wedge_mean_sin(a, b); }

double sky_view_factor(const float* horizons, int directions, std::size_t stride, WedgeRule rule) {
    return integrate(horizons, directions, stride, rule, wedge_mean_cos2);
}

double sky_visible_fraction(const float* horizons, int directions, std::size_t stride, WedgeRule rule) {
    return 1.0 - integrate(horizons, directions, stride, rule, wedge_mean_sin);
}

namespace {

// Linear wedges take the vectorised pass of visibility_products (the same means, tested
// against these per-texel functions); constant wedges, a comparison rule, stay per texel.
ProductRequest sky_request(bool svf, int threads) {
    ProductRequest r;
    r.log_sh = false;
    r.svf = svf;
    r.sky_visible = !svf;
    r.threads = threads;
    return r;
}

}  // namespace

std::vector<float> svf_raster(const HorizonSet& set, WedgeRule rule, int threads) {
    if (rule == WedgeRule::linear) {
        std::vector<float> out(set.texels());
        visibility_products_into(set, sky_request(true, threads), {nullptr, out.data(), nullptr});
        return out;
    }
    return raster(set, threads,
                  [rule](const float* h, int d, std::size_t stride) { return sky_view_factor(h, d, stride, rule); });
}

std::vector<float> sky_visible_raster(const HorizonSet& set, WedgeRule rule, int threads) {
    if (rule == WedgeRule::linear) {
        std::vector<float> out(set.texels());
        visibility_products_into(set, sky_request(false, threads), {nullptr, nullptr, out.data()});
        return out;
    }
    return raster(set, threads, [rule](const float* h, int d, std::size_t stride) {
        return sky_visible_fraction(h, d, stride, rule);
    });
}

}  // namespace ts::visibility
