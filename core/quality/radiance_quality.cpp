#include "core/quality/radiance_quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/util/error.hpp"

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

RadianceChoice choose_radiance(double max_error, const RadianceScene& scene) {
    if (!(max_error > 0))
        throw InputError("--max-error must be > 0 (a relative radiance error, e.g. 0.05 for 5%)");
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
        if (worst(s, el) <= max_error) {
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
                  "--max-error %g: %d directions, sun shadows %s (predicted relative radiance error %.3g for mean "
                  "slope %.2g = %.1f degrees, sun %.1f degrees up%s%s)",
                  max_error, c.directions, c.exact_sun ? "exact" : "sweep", c.predicted_error, scene.roughness,
                  std::atan(scene.roughness) * 180.0 / 3.14159265358979323846, c.worst_sun_elevation_deg, held,
                  c.met ? "; the cheapest setting under the bound"
                        : "; no setting is predicted under it: the finest");
    c.reason = line;
    return c;
}

}  // namespace ts::quality
