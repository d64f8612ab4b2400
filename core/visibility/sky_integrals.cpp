#include "core/visibility/sky_integrals.hpp"

#include <cmath>
#include <limits>

#include "core/util/parallel_for.hpp"

namespace ts::visibility {

namespace {

constexpr double kTiny = 1e-6;  // below this width the ramp integrals lose digits; use the midpoint

// Mean of cos^2 over sigma rising linearly from a to b, both >= 0:
// (1/(b-a)) int_a^b (1 + cos 2s)/2 ds = 1/2 + (sin 2b - sin 2a) / (4 (b - a)).
double ramp_mean_cos2(double a, double b) {
    if (std::abs(b - a) < kTiny) {
        const double c = std::cos(0.5 * (a + b));
        return c * c;
    }
    return 0.5 + (std::sin(2 * b) - std::sin(2 * a)) / (4 * (b - a));
}

// Mean of sin: (cos a - cos b) / (b - a).
double ramp_mean_sin(double a, double b) {
    if (std::abs(b - a) < kTiny) return std::sin(0.5 * (a + b));
    return (std::cos(a) - std::cos(b)) / (b - a);
}

// Splits the wedge where sigma crosses 0: below 0 the receiver sees the whole upper
// hemisphere in that azimuth (cos^2 -> 1, sin -> 0).
template <class Ramp>
double clamped_wedge_mean(double a, double b, double below_value, Ramp ramp) {
    if (a >= 0 && b >= 0) return ramp(a, b);
    if (a <= 0 && b <= 0) return below_value;
    const double t0 = a / (a - b);  // fraction of the wedge before the crossing
    if (a > 0) return t0 * ramp(a, 0.0) + (1 - t0) * below_value;
    return t0 * below_value + (1 - t0) * ramp(0.0, b);
}

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

double wedge_mean_cos2(double a, double b) {
    return clamped_wedge_mean(a, b, 1.0, ramp_mean_cos2);
}
double wedge_mean_sin(double a, double b) {
    return clamped_wedge_mean(a, b, 0.0, ramp_mean_sin);
}

double sky_view_factor(const float* horizons, int directions, std::size_t stride, WedgeRule rule) {
    return integrate(horizons, directions, stride, rule, wedge_mean_cos2);
}

double sky_visible_fraction(const float* horizons, int directions, std::size_t stride, WedgeRule rule) {
    return 1.0 - integrate(horizons, directions, stride, rule, wedge_mean_sin);
}

std::vector<float> svf_raster(const HorizonSet& set, WedgeRule rule, int threads) {
    return raster(set, threads,
                  [rule](const float* h, int d, std::size_t stride) { return sky_view_factor(h, d, stride, rule); });
}

std::vector<float> sky_visible_raster(const HorizonSet& set, WedgeRule rule, int threads) {
    return raster(set, threads, [rule](const float* h, int d, std::size_t stride) {
        return sky_visible_fraction(h, d, stride, rule);
    });
}

}  // namespace ts::visibility
