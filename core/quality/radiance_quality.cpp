#include "core/quality/radiance_quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::quality {
namespace {

std::vector<RadianceSetting> group_rows() {
    static const RadianceErrorRow rows[] = {
#include "core/quality/radiance_error_table.inc"
    };
    std::vector<RadianceSetting> out;
    for (const RadianceErrorRow& r : rows) {
        if (out.empty() || out.back().directions != r.directions || out.back().exact_sun != r.exact_sun)
            out.push_back({r.directions, r.exact_sun, {}});
        out.back().rows.push_back(r);
    }
    for (RadianceSetting& s : out)
        std::sort(s.rows.begin(), s.rows.end(),
                  [](const RadianceErrorRow& a, const RadianceErrorRow& b) { return a.sun_elevation_deg < b.sun_elevation_deg; });
    return out;
}

void check_max_error(double max_error) {
    if (!(max_error > 0))
        throw QuantityError(Quantity::max_error, "", "must be > 0 (a relative radiance error, e.g. 0.05 for 5%)");
}

}  // namespace

const std::vector<RadianceSetting>& radiance_settings() {
    static const std::vector<RadianceSetting> settings = group_rows();
    return settings;
}

double lowest_fitted_elevation() { return radiance_settings().front().rows.front().sun_elevation_deg; }
double highest_fitted_elevation() { return radiance_settings().front().rows.back().sun_elevation_deg; }

double predicted_radiance_error(const RadianceSetting& s, double roughness, double sun_elevation_deg) {
    const auto at = [&](const RadianceErrorRow& r) { return r.intercept + r.per_roughness * roughness; };
    if (sun_elevation_deg <= s.rows.front().sun_elevation_deg) return at(s.rows.front());
    if (sun_elevation_deg >= s.rows.back().sun_elevation_deg) return at(s.rows.back());
    for (std::size_t i = 1; i < s.rows.size(); ++i)
        if (sun_elevation_deg <= s.rows[i].sun_elevation_deg) {
            const RadianceErrorRow &lo = s.rows[i - 1], &hi = s.rows[i];
            const double t = (sun_elevation_deg - lo.sun_elevation_deg) / (hi.sun_elevation_deg - lo.sun_elevation_deg);
            return at(lo) + t * (at(hi) - at(lo));
        }
    return at(s.rows.back());
}

RadianceChoice choose_radiance(double max_error, const RadianceScene& scene,
                               const std::function<bool(double budget)>& rest_fits) {
    check_max_error(max_error);
    std::vector<double> suns = scene.sun_elevations_deg;
    if (suns.empty()) suns.push_back(lowest_fitted_elevation());
    // The worst sun of the scene for a setting, and its predicted error.
    const auto worst = [&](const RadianceSetting& s, double& elevation) {
        double e = -1;
        for (double el : suns)
            if (const double p = predicted_radiance_error(s, scene.roughness, el); p > e) e = p, elevation = el;
        return e;
    };
    const auto& settings = radiance_settings();
    RadianceChoice c;
    c.met = false;
    const RadianceSetting* chosen = nullptr;
    for (const RadianceSetting& s : settings)
        if (scene.exact_sun_available || !s.exact_sun) chosen = &s;  // the finest available
    for (const RadianceSetting& s : settings) {
        if (s.exact_sun && !scene.exact_sun_available) continue;
        double el = 0;
        if (const double e = worst(s, el); e <= max_error && (!rest_fits || rest_fits(max_error - e))) {
            chosen = &s;
            c.met = true;
            break;
        }
    }
    c.directions = chosen->directions;
    c.exact_sun = chosen->exact_sun;
    c.predicted_error = worst(*chosen, c.worst_sun_elevation_deg);
    const double lo = lowest_fitted_elevation();
    char held[96] = "";
    if (c.worst_sun_elevation_deg < lo) std::snprintf(held, sizeof held, ", held at the fitted %.0f", lo);
    char line[384];
    std::snprintf(line, sizeof line,
                  "%g: %d directions, sun shadows %s (predicted relative radiance error %.3g for mean "
                  "slope %.2g = %.1f degrees, sun %.1f degrees up%s%s)",
                  max_error, c.directions, c.exact_sun ? "exact" : "sweep", c.predicted_error, scene.roughness,
                  std::atan(scene.roughness) * 180.0 / 3.14159265358979323846, c.worst_sun_elevation_deg, held,
                  c.met ? "; the cheapest setting under the bound"
                        : "; no setting is predicted under it: the finest");
    c.reason = line;
    return c;
}

double relative_cost(const RadianceSetting& s) { return 60.0 + 2.2 * s.directions + (s.exact_sun ? 12.0 : 0.0); }

RegionChoice choose_radiance_per_region(double max_error, const std::vector<double>& roughness,
                                        const std::vector<double>& weight, double sun_elevation_deg,
                                        bool exact_sun_available) {
    check_max_error(max_error);
    const auto& settings = radiance_settings();
    std::vector<int> usable;  // in order of cost
    for (int i = 0; i < int(settings.size()); ++i)
        if (exact_sun_available || !settings[std::size_t(i)].exact_sun) usable.push_back(i);
    const std::size_t n = roughness.size();
    double total_w = 0;
    for (double w : weight) total_w += w;
    RegionChoice c;
    c.setting.assign(n, usable.front());
    if (n == 0 || !(total_w > 0)) return c;
    const auto square = [&](std::size_t r, int k) {
        const double e = predicted_radiance_error(settings[std::size_t(k)], roughness[r], sun_elevation_deg);
        return e * e;
    };
    double sum = 0;  // sum of w e^2
    for (std::size_t r = 0; r < n; ++r) sum += weight[r] * square(r, c.setting[r]);
    const double target = max_error * max_error * total_w;
    while (sum > target) {
        // The upgrade (a region, a costlier setting) with the largest fall of w e^2 per cost.
        double best = 0, best_gain = 0;
        std::size_t best_r = n;
        int best_k = -1;
        for (std::size_t r = 0; r < n; ++r) {
            const double now = square(r, c.setting[r]), now_cost = relative_cost(settings[std::size_t(c.setting[r])]);
            for (int k : usable) {
                const double cost = relative_cost(settings[std::size_t(k)]) - now_cost;
                const double gain = weight[r] * (now - square(r, k));
                if (cost <= 0 || gain <= 0) continue;
                if (gain / cost > best) best = gain / cost, best_gain = gain, best_r = r, best_k = k;
            }
        }
        if (best_r == n) {
            c.met = false;
            break;
        }
        c.setting[best_r] = best_k;
        sum -= best_gain;
    }
    c.predicted_error = std::sqrt(std::max(0.0, sum) / total_w);
    return c;
}

}  // namespace ts::quality
