#include "core/solar/insolation_reference.hpp"

#include <algorithm>
#include <cmath>

#include "core/solar/esra_clear_sky.hpp"
#include "core/solar/sun_path.hpp"
#include "core/util/angles.hpp"
#include "core/visibility/sun_visibility.hpp"

namespace ts::solar {

std::vector<double> reference_insolation(const InsolationSettings& settings, double latitude_deg, double z_m,
                                         const glm::dvec3& n, const std::vector<float>& horizons) {
    check_settings(settings);
    return reference_insolation(settings,
                                sample_sun_path(settings.periods, settings.step_minutes, settings.clock_longitude_deg),
                                latitude_deg, z_m, n, horizons);
}

std::vector<double> reference_insolation(const InsolationSettings& settings, const std::vector<EphemerisSample>& path,
                                         double latitude_deg, double z_m, const glm::dvec3& n,
                                         const std::vector<float>& horizons) {
    const int periods = int(settings.periods.size());
    std::vector<double> beam(std::size_t(periods), 0.0), circ = beam, iso = beam, open = beam, hours = beam;
    const int count = int(horizons.size());
    const double nz = std::max(n.z, 1e-6);
    for (const EphemerisSample& s : path) {
        const LocalSun sun = local_sun(s, latitude_deg, settings.clock_longitude_deg, settings.refraction);
        if (!(sun.elevation_rad > 0)) continue;
        const double x = sun.phi_rad / (2 * kPi) * count;
        const int k = int(x) % count;
        const double f = x - std::floor(x);
        const double h_grid = horizons[std::size_t(k)] + f * (horizons[std::size_t((k + 1) % count)] - horizons[std::size_t(k)]);
        const double a = n.x * std::cos(sun.phi_rad) + n.y * std::sin(sun.phi_rad);
        const double h = std::max(h_grid, std::atan(-a / nz));
        const double visible = visibility::sun_disc_visible_fraction(h, sun.elevation_rad, settings.sun_radius_rad);
        const double g0 = extraterrestrial_normal_irradiance(s.day_of_year);
        const double tl = settings.linke_monthly[std::size_t(s.month0)];
        const double b = beam_normal_irradiance(g0, tl, sun.altitude_rad, z_m);
        const double d = diffuse_horizontal_irradiance(g0, tl, sun.altitude_rad);
        const double kb = g0 > 0 ? b / g0 : 0.0;
        const double sin_e = sun.direction.z;
        const double c = sin_e > 1e-3 ? d * kb / sin_e : 0.0;
        const double cos_i = std::max(0.0, glm::dot(n, sun.direction));
        const auto p = std::size_t(s.period);
        beam[p] += b * cos_i * visible * s.hours;
        circ[p] += c * cos_i * visible * s.hours;
        iso[p] += (d - c * sin_e) * s.hours;
        open[p] += (b * sin_e + d) * s.hours;
        hours[p] += visible * s.hours;
    }
    const double svf = tilted_sky_view_factor(horizons.data(), count, n);
    const double k = settings.clear_sky_index / 1000.0;
    std::vector<double> out(std::size_t(periods) * kQuantities);
    for (std::size_t p = 0; p < std::size_t(periods); ++p) {
        double* o = out.data() + p * kQuantities;
        o[kBeam] = beam[p] * k;
        o[kDiffuse] = (circ[p] + iso[p] * svf) * k;
        o[kReflected] = settings.albedo * open[p] * (1 - svf) * k;
        o[kGlobal] = o[kBeam] + o[kDiffuse] + o[kReflected];
        o[kSunHours] = hours[p];
    }
    return out;
}

}  // namespace ts::solar
