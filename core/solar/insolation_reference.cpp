#include "core/solar/insolation_reference.hpp"

#include <algorithm>
#include <cmath>

#include "core/solar/cie_clear_sky.hpp"
#include "core/solar/esra_clear_sky.hpp"
#include "core/solar/sun_path.hpp"
#include "core/util/angles.hpp"
#include "core/visibility/sun_visibility.hpp"

namespace ts::solar {
namespace {

// The horizon at azimuth phi in [0, 2 pi), linear between the given azimuths.
double horizon_at(const std::vector<float>& horizons, double phi) {
    const int count = int(horizons.size());
    const double x = phi / (2 * kPi) * count;
    const int k = int(std::floor(x)) % count;
    const double f = x - std::floor(x);
    return horizons[std::size_t(k)] + f * (horizons[std::size_t((k + 1) % count)] - horizons[std::size_t(k)]);
}

// The sky a texel sees as quadrature points: direction, the sun-independent gradation folded
// into the weight (radiance = indicatrix x gradation) times (n . w) dOmega.
struct SkyPoints {
    std::vector<glm::dvec3> w;
    std::vector<double> weight;
};

// Under horizons (with the receiver's plane), or the open upper hemisphere of a horizontal
// plane (horizons empty, n up).
SkyPoints visible_sky(const glm::dvec3& n, const std::vector<float>& horizons, int azimuths, int elevations) {
    SkyPoints pts;
    const double nz = std::max(n.z, 1e-6), dphi = 2 * kPi / azimuths;
    for (int i = 0; i < azimuths; ++i) {
        const double phi = dphi * i;
        double lo = 0;
        if (!horizons.empty()) {
            const double a = n.x * std::cos(phi) + n.y * std::sin(phi);
            lo = std::max(horizon_at(horizons, phi), std::atan(-a / nz));
        }
        const double de = (kPi / 2 - lo) / elevations;
        for (int k = 0; k < elevations; ++k) {
            const double e = lo + (k + 0.5) * de;
            const glm::dvec3 w(std::cos(e) * std::cos(phi), std::cos(e) * std::sin(phi), std::sin(e));
            const double cosine = std::max(0.0, glm::dot(n, w));
            pts.w.push_back(w);
            pts.weight.push_back(cie_clear_sky_gradation(w.z) * cosine * std::cos(e) * de * dphi);
        }
    }
    return pts;
}

double sky_integral(const SkyPoints& pts, const glm::dvec3& sun) {
    double sum = 0;
    for (std::size_t i = 0; i < pts.w.size(); ++i) sum += pts.weight[i] * cie_clear_sky_indicatrix(glm::dot(sun, pts.w[i]));
    return sum;
}

}  // namespace

std::vector<double> reference_insolation(const InsolationSettings& settings, double latitude_deg, double z_m,
                                         const glm::dvec3& n, const std::vector<float>& horizons, const ReferenceSky& sky) {
    check_settings(settings);
    return reference_insolation(settings,
                                sample_sun_path(settings.periods, settings.step_minutes, settings.clock_longitude_deg),
                                latitude_deg, z_m, n, horizons, sky);
}

std::vector<double> reference_insolation(const InsolationSettings& settings, const std::vector<EphemerisSample>& path,
                                         double latitude_deg, double z_m, const glm::dvec3& n,
                                         const std::vector<float>& horizons, const ReferenceSky& sky) {
    const int periods = int(settings.periods.size());
    std::vector<double> beam(std::size_t(periods), 0.0), diffuse = beam, open = beam, hours = beam;
    const int count = int(horizons.size());
    const double nz = std::max(n.z, 1e-6);
    const int sky_azimuths = sky.azimuths > 0 ? sky.azimuths : count;
    const SkyPoints seen = visible_sky(n, horizons, sky_azimuths, sky.elevations);
    // The normalisation: the open sky on a horizontal plane, a function of the sun's elevation
    // only, every degree (linear between: it is smooth), at twice the resolution.
    std::vector<double> open_sky(91);
    {
        const SkyPoints up = visible_sky({0, 0, 1}, {}, 2 * sky_azimuths, 2 * sky.elevations);
        for (int e = 0; e <= 90; ++e)
            open_sky[std::size_t(e)] = sky_integral(up, {std::cos(radians(e)), 0.0, std::sin(radians(e))});
    }
    auto open_sky_at = [&](double elevation_rad) {
        const double x = std::clamp(degrees(elevation_rad), 0.0, 90.0);
        const int e = std::min(int(x), 89);
        return open_sky[std::size_t(e)] + (x - e) * (open_sky[std::size_t(e + 1)] - open_sky[std::size_t(e)]);
    };
    const int stride = std::max(1, sky.stride);
    std::size_t group = std::size_t(-1);
    double seen_share = 0;  // seen sky / horizontal, for the current group of steps
    for (std::size_t i = 0; i < path.size(); ++i) {
        const EphemerisSample& s = path[i];
        const LocalSun sun = local_sun(s, latitude_deg, settings.clock_longitude_deg, settings.refraction,
                                         settings.grid_north_deg);
        if (!(sun.elevation_rad > 0)) continue;
        if (i / std::size_t(stride) != group) {
            group = i / std::size_t(stride);
            // The group's middle step when the sun is up then, else this one.
            std::size_t mid = std::min(path.size() - 1, group * std::size_t(stride) + std::size_t(stride) / 2);
            LocalSun at = local_sun(path[mid], latitude_deg, settings.clock_longitude_deg, settings.refraction,
                                settings.grid_north_deg);
            if (!(at.elevation_rad > 0)) at = sun;
            seen_share = sky_integral(seen, at.direction) / open_sky_at(at.elevation_rad);
        }
        const double h_grid = horizon_at(horizons, sun.phi_rad);
        const double a = n.x * std::cos(sun.phi_rad) + n.y * std::sin(sun.phi_rad);
        const double h = std::max(h_grid, std::atan(-a / nz));
        const double visible = visibility::sun_disc_visible_fraction(h, sun.elevation_rad, settings.sun_radius_rad);
        const double g0 = extraterrestrial_normal_irradiance(s.day_of_year);
        const double tl = settings.linke_monthly[std::size_t(s.month0)];
        const double b = beam_normal_irradiance(g0, tl, sun.altitude_rad, z_m);
        const double d = diffuse_horizontal_irradiance(g0, tl, sun.altitude_rad);
        const double cos_i = std::max(0.0, glm::dot(n, sun.direction));
        const auto p = std::size_t(s.period);
        beam[p] += b * cos_i * visible * s.hours;
        diffuse[p] += d * seen_share * s.hours;
        open[p] += (b * sun.direction.z + d) * s.hours;
        hours[p] += visible * s.hours;
    }
    const double svf = tilted_sky_view_factor(horizons.data(), count, n);
    const double k = settings.clear_sky_index / 1000.0;
    std::vector<double> out(std::size_t(periods) * kQuantities);
    for (std::size_t p = 0; p < std::size_t(periods); ++p) {
        double* o = out.data() + p * kQuantities;
        o[kBeam] = beam[p] * k;
        o[kDiffuse] = diffuse[p] * k;
        o[kReflected] = settings.albedo * open[p] * (1 - svf) * k;
        o[kGlobal] = o[kBeam] + o[kDiffuse] + o[kReflected];
        o[kSunHours] = hours[p];
    }
    return out;
}

}  // namespace ts::solar
