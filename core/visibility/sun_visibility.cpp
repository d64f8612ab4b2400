// The sun's visible fraction: the exact method's sweep for the one azimuth of the sun
// (exact_azimuth.hpp), then the area of the sun's disc above that horizon.
#include "core/visibility/sun_visibility.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <thread>

#include "core/geo/azimuth.hpp"
#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/exact_azimuth.hpp"
#include "core/visibility/sun_disc_shared.hpp"

namespace ts::visibility {
namespace {

void check_grid(const terrain::HeightGrid& grid) {
    if (grid.width < 1 || grid.height < 1 || grid.z.size() != std::size_t(grid.width) * std::size_t(grid.height))
        throw InputError("height grid: empty or inconsistent size");
}

// Runs job(t) for t in [0, n) on n threads (the caller's included).
template <class Job>
void run_on_threads(int n, Job&& job) {
    std::vector<std::jthread> pool;
    pool.reserve(std::size_t(std::max(0, n - 1)));
    for (int t = 1; t < n; ++t) pool.emplace_back([&job, t] { job(t); });
    job(0);
}

// The exact horizon in one azimuth, with the near field cut short outside [band_lo, band_hi]
// (tangents; exact_azimuth.hpp, finish_rows).
std::vector<float> horizon_in_azimuth(const terrain::HeightGrid& grid, double phi_rad, const HorizonOptions& options,
                                      double band_lo, double band_hi) {
    check_grid(grid);
    const ExactAzimuthSweep sweep(grid, options);
    const ReceiverWindow& win = sweep.window();
    std::vector<float> plane(sweep.texels(), std::numeric_limits<float>::quiet_NaN());
    const SweepPlan plan = sweep.plan(phi_rad);
    // Lines split into contiguous ranges, one per thread with its own hull and sums; the sums
    // are then added in line order, so a texel's total differs from one thread's by rounding of
    // the association only (a texel lies between two lines, rarely three).
    const int threads = int(std::clamp<long>(thread_count(options.threads), 1, std::max(1L, plan.lines())));
    std::vector<FarFieldSums> sums;
    sums.reserve(std::size_t(threads));
    for (int t = 0; t < threads; ++t) sums.push_back(sweep.make_sums());
    run_on_threads(threads, [&](int t) {
        const long begin = plan.n_min + plan.lines() * t / threads;
        const long end = plan.n_min + plan.lines() * (t + 1) / threads;
        sweep.sweep_far_field(plan, begin, end, sums[std::size_t(t)]);
    });
    // Rows in bands: add the other threads' sums into the first's, then march the near field.
    run_on_threads(threads, [&](int t) {
        const int lr0 = int((long long)win.height * t / threads), lr1 = int((long long)win.height * (t + 1) / threads);
        const std::size_t i0 = std::size_t(lr0) * win.width, i1 = std::size_t(lr1) * win.width;
        float* sum = sums[0].sum.data();
        float* weight = sums[0].weight.data();
        float* empty_weight = sums[0].empty_weight.data();
        for (int k = 1; k < threads; ++k) {
            const FarFieldSums& other = sums[std::size_t(k)];
            for (std::size_t i = i0; i < i1; ++i)
                sum[i] += other.sum[i], weight[i] += other.weight[i], empty_weight[i] += other.empty_weight[i];
        }
        sweep.finish_rows(plan.phi, sum, weight, empty_weight, lr0, lr1, plane.data(), band_lo, band_hi);
    });
    return plane;
}

}  // namespace

SunMethod parse_sun_method(const std::string& name) {
    if (name == "sweep") return SunMethod::sweep;
    if (name == "exact") return SunMethod::exact;
    throw InputError("sun shadows: unknown method '" + name + "' (choose sweep or exact)");
}

std::string sun_method_name(SunMethod method) {
    return method == SunMethod::exact ? "exact" : "sweep";
}

double sun_disc_visible_fraction(double horizon_rad, double sun_elevation_rad, double sun_radius_rad) {
    if (std::isnan(horizon_rad) || std::isnan(sun_elevation_rad)) return std::numeric_limits<double>::quiet_NaN();
    if (!(sun_radius_rad > 0)) return sun_elevation_rad > horizon_rad ? 1.0 : 0.0;  // a point sun
    return shared::ts_sun_disc_fraction((sun_elevation_rad - horizon_rad) / sun_radius_rad);
}

double horizon_above_sun_for_fraction(double fraction, double sun_radius_rad) {
    // Most texels see all of the disc or none of it.
    const double v = std::clamp(fraction, 0.0, 1.0);
    if (v >= 1.0) return -sun_radius_rad;
    if (v <= 0.0) return sun_radius_rad;
    // The fraction falls monotonically with the horizon: bisect x = (e - h) / r on [-1, 1].
    double lo = -1.0, hi = 1.0;
    for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        (shared::ts_sun_disc_fraction(mid) < v ? lo : hi) = mid;
    }
    return -0.5 * (lo + hi) * sun_radius_rad;
}

std::vector<float> exact_horizon_in_azimuth(const terrain::HeightGrid& grid, double phi_rad,
                                            const HorizonOptions& options) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    return horizon_in_azimuth(grid, phi_rad, options, -kInf, kInf);
}

std::vector<float> sun_visibility(const terrain::HeightGrid& grid, double sun_azimuth_deg, double sun_elevation_deg,
                                  const SunVisibilityOptions& options, std::vector<float>* horizon_above_sun) {
    if (!std::isfinite(sun_azimuth_deg) || !std::isfinite(sun_elevation_deg) || sun_elevation_deg < -90.0 ||
        sun_elevation_deg > 90.0)
        throw InputError("sun position: azimuth must be finite and elevation within [-90, 90] degrees");
    if (!(options.sun_radius_rad >= 0) || options.sun_radius_rad > 0.1)
        throw InputError("sun radius: must be between 0 and 0.1 rad, got " + std::to_string(options.sun_radius_rad));
    HorizonOptions h;
    h.curvature = options.curvature;
    h.exact_near_field_texels = options.near_field_texels;
    h.exact_lines_per_texel = options.lines_per_texel;
    h.window = options.window;
    h.threads = options.threads;
    const double e = radians(sun_elevation_deg);
    // Only horizons across the disc change the fraction; the band is widened by 1e-5 rad to
    // cover fast_atan's 1.7e-6 rad error, so the fraction is the same as from the full horizon.
    constexpr double kInf = std::numeric_limits<double>::infinity(), kSlack = 1e-5;
    const double half_band = horizon_above_sun ? std::max(options.sun_radius_rad, kSunHorizonBandRad) : options.sun_radius_rad;
    const double lo = e - half_band - kSlack, hi = e + half_band + kSlack;
    const double band_lo = lo <= -kPi / 2 ? -kInf : std::tan(lo);
    const double band_hi = hi >= kPi / 2 ? kInf : std::tan(hi);
    std::vector<float> horizon =
        horizon_in_azimuth(grid, geo::azimuth_cw_from_north_to_phi(sun_azimuth_deg), h, band_lo, band_hi);
    if (horizon_above_sun) {
        horizon_above_sun->resize(horizon.size());
        for (std::size_t t = 0; t < horizon.size(); ++t)
            (*horizon_above_sun)[t] = std::isnan(horizon[t])
                                          ? horizon[t]
                                          : float(std::clamp(double(horizon[t]) - e, -kSunHorizonBandRad, kSunHorizonBandRad));
    }
    for (float& v : horizon)  // NaN (void receiver) stays NaN
        if (!std::isnan(v)) v = float(sun_disc_visible_fraction(v, e, options.sun_radius_rad));
    return horizon;
}

}  // namespace ts::visibility
