#include "core/light/physical_sky.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/light/sky_color.hpp"
#include "core/light/sky_quadrature.hpp"
#include "core/light/sun_transmittance.hpp"
#include "core/util/angles.hpp"

namespace ts::light {

namespace {

using atmosphere::Densities;
using atmosphere::SunPathTable;
using atmosphere::kWavelengths;
using atmosphere::wavelength_nm;

// The observer: sea level (the dome changes little over a terrain's few kilometres).
constexpr double kObserverRadiusM = atmosphere::kEarthRadiusM + 1.0;

// The dome's table: elevations dense near the horizon (e = 90 deg v^2), azimuths from the sun.
constexpr int kTableElevations = 40;
constexpr int kTableAzimuths = 12;
constexpr int kViewSteps = 32;

// Planck's law, up to a constant, at wavelength nm and temperature kelvin.
double black_body(double nm, double kelvin) {
    const double lambda_um = nm * 1e-3;
    return 1.0 / (std::pow(lambda_um, 5.0) * (std::exp(14387.77 / (lambda_um * kelvin)) - 1.0));
}

// The colour-matching functions integrated against the spectrum's piecewise-linear
// interpolation between the samples (held constant beyond the first and last).
std::array<glm::dvec3, kWavelengths> sample_weights_xyz() {
    std::array<glm::dvec3, kWavelengths> w{};
    for (double nm = 360.0; nm <= 830.0; nm += 1.0) {
        const glm::dvec3 cmf = cie_1931_color_matching(nm);
        const double pos = (nm - atmosphere::kFirstWavelengthNm) / atmosphere::kWavelengthStepNm;
        if (pos <= 0.0) {
            w[0] += cmf;
        } else if (pos >= kWavelengths - 1) {
            w[kWavelengths - 1] += cmf;
        } else {
            const int k = int(pos);
            const double f = pos - k;
            w[std::size_t(k)] += cmf * (1.0 - f);
            w[std::size_t(k + 1)] += cmf * f;
        }
    }
    return w;
}

double rayleigh_phase(double cos_gamma) {
    return 3.0 / (16.0 * kPi) * (1.0 + cos_gamma * cos_gamma);
}

double mie_phase(double cos_gamma) {
    const double g = atmosphere::kMieAsymmetry;
    const double denom = std::max(1e-9, 1.0 + g * g - 2.0 * g * cos_gamma);
    return 3.0 / (8.0 * kPi) * (1.0 - g * g) * (1.0 + cos_gamma * cos_gamma) / ((2.0 + g * g) * denom * std::sqrt(denom));
}

}  // namespace

PhysicalSky::PhysicalSky(double turbidity, double ground_albedo, const glm::dvec3& sun_direction_enu,
                         Scattering scattering)
    : PhysicalSky(Aerosol{angstrom_beta(turbidity), 1.3}, ground_albedo, sun_direction_enu, scattering, turbidity) {}

PhysicalSky::PhysicalSky(const Aerosol& aerosol, double ground_albedo, const glm::dvec3& sun_direction_enu,
                         Scattering scattering, double turbidity)
    : PhysicalSky(atmosphere::coefficients_for(aerosol),
                  scattering == Scattering::multiple ? MultipleScattering::shared(aerosol, ground_albedo) : nullptr,
                  ground_albedo, sun_direction_enu, turbidity) {}

PhysicalSky::PhysicalSky(const atmosphere::Coefficients& coefficients, double ground_albedo,
                         const glm::dvec3& sun_direction_enu, Scattering scattering)
    : PhysicalSky(coefficients,
                  scattering == Scattering::multiple ? std::make_shared<MultipleScattering>(coefficients, ground_albedo)
                                                     : nullptr,
                  ground_albedo, sun_direction_enu, 0.0) {}

PhysicalSky::PhysicalSky(const atmosphere::Coefficients& coefficients, std::shared_ptr<const MultipleScattering> multiple,
                         double ground_albedo, const glm::dvec3& sun_direction_enu, double turbidity)
    : turbidity_(turbidity), albedo_(ground_albedo), coefficients_(coefficients), multiple_(std::move(multiple)) {
    glm::dvec3 s = sun_direction_enu;
    const double len = std::sqrt(s.x * s.x + s.y * s.y + s.z * s.z);
    s = (std::isfinite(len) && len > 0.0) ? s / len : glm::dvec3(0.0, 0.0, 1.0);
    sun_dir_ = s;
    const double h = std::hypot(s.x, s.y);
    sun_east_ = h > 1e-9 ? glm::dvec3(s.x / h, s.y / h, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
    sun_north_ = glm::dvec3(-sun_east_.y, sun_east_.x, 0.0);

    // The extraterrestrial sun per wavelength through the colour matching into linear RGB,
    // scaled so its luminance is the luminous solar constant.
    const std::array<glm::dvec3, kWavelengths> cmf = sample_weights_xyz();
    double luminance_sum = 0.0;
    for (int k = 0; k < kWavelengths; ++k) luminance_sum += black_body(wavelength_nm(k), kSunTemperatureK) * cmf[std::size_t(k)].y;
    for (int k = 0; k < kWavelengths; ++k) {
        const glm::dvec3 xyz = cmf[std::size_t(k)] * (black_body(wavelength_nm(k), kSunTemperatureK) *
                                                      kSolarIlluminanceKlx / luminance_sum);
        weight_[std::size_t(k)] = xyz_to_linear_srgb(xyz.x, xyz.y, xyz.z);
    }

    // The sun's beam: the same atmosphere from the observer. Zero once the disc has set.
    if (std::asin(std::clamp(s.z, -1.0, 1.0)) >= -sun_.angular_radius_rad) {
        const Densities path = SunPathTable::instance().at(kObserverRadiusM - atmosphere::kEarthRadiusM, std::max(s.z, 0.0));
        const atmosphere::Coefficients& c = coefficients_;
        Rgb e(0.0f);
        for (int k = 0; k < kWavelengths; ++k) {
            const std::size_t kk = std::size_t(k);
            const double t = std::exp(-(c.rayleigh[kk] * path.rayleigh + c.mie_extinction[kk] * path.mie + c.ozone[kk] * path.ozone));
            e += weight_[kk] * static_cast<float>(t);
        }
        sun_.irradiance = glm::max(e, Rgb(0.0f));
    }
    sun_.direction = s;

    table_.resize(std::size_t(kTableElevations) * kTableAzimuths);
    for (int i = 0; i < kTableElevations; ++i) {
        const double v = double(i) / (kTableElevations - 1);
        const double elevation = 0.5 * kPi * v * v;
        for (int j = 0; j < kTableAzimuths; ++j) {
            const double phi = kPi * j / (kTableAzimuths - 1);
            table_[std::size_t(i) * kTableAzimuths + std::size_t(j)] = integrate(view_direction(elevation, phi));
        }
    }

    // Ground: a Lambertian plane lit by the dome and the sun's beam.
    glm::dvec3 e(0.0);
    for_each_sky_node(HemisphereRule{24, 96}, false, [&](const glm::dvec3& d, double w) {
        e += glm::dvec3(sky_radiance(d)) * (w * d.z);
    });
    sky_horizontal_ = Rgb(e);
    const Rgb sun_horizontal = sun_.irradiance * static_cast<float>(std::max(0.0, s.z));
    ground_ = (sky_horizontal_ + sun_horizontal) * static_cast<float>(albedo_ / kPi);
}

glm::dvec3 PhysicalSky::view_direction(double elevation, double phi) const {
    const double c = std::cos(elevation);
    return sun_east_ * (c * std::cos(phi)) + sun_north_ * (c * std::sin(phi)) + glm::dvec3(0.0, 0.0, std::sin(elevation));
}

// Along the view ray from the observer, at each step: the light of the sun that reached it
// (the sun path's transmittance) scattered towards the observer once, plus the light scattered
// there more than once (Psi), both dimmed on the way back (the view path's transmittance). The
// single-scattering phase functions are the same at every step (the sun is at infinity), so
// they are left out and applied per direction. With multiple scattering the view path is
// dimmed by the delta-scaled atmosphere (MultipleScattering::medium()): light the aerosol
// scatters forward along it stays in it, as the path tracer's does (without that the dome near
// the horizon came out 25-45% too dark against tests/light/sky_path_tracer.cpp). The sun's path
// keeps the whole extinction: scaled too, it kept the forward-scattered sunlight in the beam
// and the exact phase's peak counted it again, an aureole 30-150% too bright.
PhysicalSky::NodeRadiance PhysicalSky::integrate(const glm::dvec3& view) const {
    const double mu = std::clamp(view.z, 0.0, 1.0);
    const double d = atmosphere::distance_to_top(kObserverRadiusM, mu);
    const SunPathTable& sun_paths = SunPathTable::instance();
    const atmosphere::Coefficients& c = coefficients_;
    const atmosphere::Coefficients& tc = multiple_ ? multiple_->medium() : coefficients_;
    // The spectral loop in float: 17 exponentials a step are most of a sky's cost, and float's
    // 1e-7 is far below the table's 2% interpolation error.
    std::array<float, kWavelengths> sum_r{}, sum_m{}, sum_ms{};
    atmosphere::Spectrum psi{};
    Densities behind;  // integrated along the view ray up to the current step
    for (int k = 0; k < kViewSteps; ++k) {
        const double u = (k + 0.5) / kViewSteps;
        const double t = d * u * u;
        const double dt = 2.0 * d * u / kViewSteps;
        const glm::dvec3 p = glm::dvec3(0.0, 0.0, kObserverRadiusM) + view * t;
        const double r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
        const double altitude = r - atmosphere::kEarthRadiusM;
        const double sin_sun = (p.x * sun_dir_.x + p.y * sun_dir_.y + p.z * sun_dir_.z) / r;
        const Densities rho = atmosphere::densities_at(altitude);
        const Densities to_sun = sun_paths.at(altitude, sin_sun);
        const Densities here{behind.rayleigh + 0.5 * rho.rayleigh * dt, behind.mie + 0.5 * rho.mie * dt,
                             behind.ozone + 0.5 * rho.ozone * dt};
        behind.rayleigh += rho.rayleigh * dt;
        behind.mie += rho.mie * dt;
        behind.ozone += rho.ozone * dt;
        const float w_r = float(rho.rayleigh * dt), w_m = float(rho.mie * dt);
        if (multiple_) {
            multiple_->at(altitude, sin_sun, psi);
            const atmosphere::Coefficients& cm = multiple_->medium();
            const float view_r = float(here.rayleigh), view_m = float(here.mie), view_o = float(here.ozone);
            for (std::size_t w = 0; w < kWavelengths; ++w) {
                const float transmittance = std::exp(-(cm.rayleigh[w] * view_r + cm.mie_extinction[w] * view_m + cm.ozone[w] * view_o));
                sum_ms[w] += transmittance * (cm.rayleigh[w] * w_r + cm.mie_scattering[w] * w_m) * psi[w];
            }
        }
        if (SunPathTable::blocked(to_sun)) continue;  // in the Earth's shadow
        const float view_r = float(here.rayleigh), view_m = float(here.mie), view_o = float(here.ozone);
        const float sun_r = float(to_sun.rayleigh), sun_m = float(to_sun.mie), sun_o = float(to_sun.ozone);
        for (std::size_t w = 0; w < kWavelengths; ++w) {
            const float transmittance = std::exp(-(tc.rayleigh[w] * view_r + tc.mie_extinction[w] * view_m + tc.ozone[w] * view_o +
                                                   c.rayleigh[w] * sun_r + c.mie_extinction[w] * sun_m + c.ozone[w] * sun_o));
            sum_r[w] += transmittance * w_r;
            sum_m[w] += transmittance * w_m;
        }
    }
    NodeRadiance out;
    for (std::size_t w = 0; w < kWavelengths; ++w) {
        out.rayleigh += weight_[w] * (c.rayleigh[w] * sum_r[w]);
        out.mie += weight_[w] * (c.mie_scattering[w] * sum_m[w]);
        out.multiple += weight_[w] * sum_ms[w];
    }
    return out;
}

PhysicalSky::NodeRadiance PhysicalSky::node_at(const glm::dvec3& dir) const {
    // Written so that a NaN direction reads node 0 instead of converting NaN to an index.
    const double z = dir.z > 0.0 ? std::min(dir.z, 1.0) : 0.0;
    const double elevation = std::asin(z);
    const double along = dir.x * sun_east_.x + dir.y * sun_east_.y;
    const double across = std::abs(dir.x * sun_north_.x + dir.y * sun_north_.y);
    const double angle = std::atan2(across, along);
    const double phi = angle >= 0.0 ? angle : 0.0;
    const double a = std::sqrt(elevation / (0.5 * kPi)) * (kTableElevations - 1);
    const double b = phi / kPi * (kTableAzimuths - 1);
    const int i = std::min(int(a), kTableElevations - 2);
    const int j = std::min(int(b), kTableAzimuths - 2);
    const float fa = static_cast<float>(std::min(a - i, 1.0)), fb = static_cast<float>(std::min(b - j, 1.0));
    auto node = [&](int di, int dj) -> const NodeRadiance& {
        return table_[std::size_t(i + di) * kTableAzimuths + std::size_t(j + dj)];
    };
    NodeRadiance n;
    n.rayleigh = (node(0, 0).rayleigh * (1 - fb) + node(0, 1).rayleigh * fb) * (1 - fa) +
                 (node(1, 0).rayleigh * (1 - fb) + node(1, 1).rayleigh * fb) * fa;
    n.mie = (node(0, 0).mie * (1 - fb) + node(0, 1).mie * fb) * (1 - fa) + (node(1, 0).mie * (1 - fb) + node(1, 1).mie * fb) * fa;
    n.multiple = (node(0, 0).multiple * (1 - fb) + node(0, 1).multiple * fb) * (1 - fa) +
                 (node(1, 0).multiple * (1 - fb) + node(1, 1).multiple * fb) * fa;
    return n;
}

Rgb PhysicalSky::dome(const glm::dvec3& dir, double mie_phase_cap) const {
    const double z = dir.z > 0.0 ? std::min(dir.z, 1.0) : 0.0;
    return with_phases(node_at(dir), glm::normalize(glm::dvec3(dir.x, dir.y, z)), mie_phase_cap);
}

Rgb PhysicalSky::sky_radiance(const glm::dvec3& dir) const {
    return dome(dir, 1e300);
}

Rgb PhysicalSky::lighting_radiance(const glm::dvec3& dir) const {
    return dir.z > 0.0 ? dome(dir, aureole_phase_cap_) : ground_;
}

void PhysicalSky::light_aureole_with_sun(double max_half_angle_deg) {
    const double sun_elevation = std::asin(std::clamp(sun_dir_.z, -1.0, 1.0));
    const double cap = std::min(max_half_angle_deg * kPi / 180.0, sun_elevation);
    const bool disc_up = sun_.irradiance.x > 0 || sun_.irradiance.y > 0 || sun_.irradiance.z > 0;
    if (!(cap > sun_.angular_radius_rad) || !disc_up) return;
    const double edge = mie_phase(std::cos(cap));
    // The cap's Mie light above the edge's phase on a horizontal surface, over the sun's
    // sine: the irradiance a beam from the sun needs to give flat ground the same light. (The
    // cap's light grows towards the horizon, so its centroid sits below the sun: projected on
    // the sun's direction it gave flat ground 1.3% more light at 20 degrees.) Rings dense near
    // the sun (g = cap v^2), where the phase peaks.
    const glm::dvec3 s = sun_dir_;
    const glm::dvec3 t1 = sun_north_;
    const glm::dvec3 t2 = glm::cross(s, t1);
    constexpr int kRings = 48, kAround = 48;
    glm::dvec3 e(0.0);
    for (int i = 0; i < kRings; ++i) {
        const double v = (i + 0.5) / kRings;
        const double g = cap * v * v, dg = 2.0 * cap * v / kRings;
        const double excess = mie_phase(std::cos(g)) - edge;
        const double d_omega = std::sin(g) * dg * (2.0 * kPi / kAround);
        for (int j = 0; j < kAround; ++j) {
            const double psi = 2.0 * kPi * (j + 0.5) / kAround;
            const glm::dvec3 w = s * std::cos(g) + (t1 * std::cos(psi) + t2 * std::sin(psi)) * std::sin(g);
            if (w.z <= 0.0) continue;
            e += glm::dvec3(node_at(w).mie) * (excess * d_omega * w.z);
        }
    }
    e /= s.z;
    sun_.aureole = glm::max(Rgb(e), Rgb(0.0f));
    sun_.irradiance += sun_.aureole;
    aureole_phase_cap_ = edge;
}

Rgb PhysicalSky::sky_radiance_integrated(const glm::dvec3& dir) const {
    const glm::dvec3 v = glm::normalize(glm::dvec3(dir.x, dir.y, std::max(dir.z, 0.0)));
    return with_phases(integrate(v), v);
}

Rgb PhysicalSky::with_phases(const NodeRadiance& n, const glm::dvec3& unit_view, double mie_phase_cap) const {
    const double cos_gamma = std::clamp(glm::dot(unit_view, sun_dir_), -1.0, 1.0);
    const Rgb l = n.rayleigh * static_cast<float>(rayleigh_phase(cos_gamma)) +
                  n.mie * static_cast<float>(std::min(mie_phase(cos_gamma), mie_phase_cap)) + n.multiple;
    return glm::max(l, Rgb(0.0f));
}

Rgb PhysicalSky::radiance(const glm::dvec3& dir) const {
    return dir.z > 0.0 ? sky_radiance(dir) : ground_;
}

std::string PhysicalSky::describe() const {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "clear sky (physical, %s scattering), turbidity %.2f, ground albedo %.2f, zenith %.2f kcd/m2",
                  multiple_ ? "multiple" : "single", turbidity_, albedo_, luminance(sky_radiance(glm::dvec3(0.0, 0.0, 1.0))));
    return buf;
}

}  // namespace ts::light
