#include "core/light/physical_sky.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/light/sky_color.hpp"
#include "core/light/sky_quadrature.hpp"
#include "core/light/sun_transmittance.hpp"
#include "core/util/angles.hpp"

namespace ts::light {

namespace {

// The atmosphere: Bruneton & Neyret (2008)'s radii and scale heights. Air's and aerosol's
// vertical optical depths are those of the sun's beam model (sun_transmittance.hpp) spread
// over their scale heights, so a turbidity means the same aerosol load for the disc and the dome.
constexpr double kEarthRadiusM = 6360e3;
constexpr double kTopRadiusM = 6420e3;
constexpr double kAtmosphereHeightM = kTopRadiusM - kEarthRadiusM;
constexpr double kRayleighScaleHeightM = 8000.0;
constexpr double kMieScaleHeightM = 1200.0;
// Cornette & Shanks (1992)'s phase function with a continental aerosol's asymmetry; the
// aerosol scatters 90% of what it takes out of a beam (the rest is absorbed).
constexpr double kMieAsymmetry = 0.76;
constexpr double kAerosolSingleScatteringAlbedo = 0.9;
// Ozone: 300 Dobson units (2.687e20 molecules/m^2 each) in a layer peaking at 25 km and gone
// at 10 and 40 km; its Chappuis band as a split Gaussian, 5.0e-25 m^2 at 603 nm, falling to
// half 75 nm below and 58 nm above (a fit to the band's measured cross-sections).
constexpr double kOzoneColumnPerM2 = 300.0 * 2.687e20;
constexpr double kOzonePeakM = 25e3;
constexpr double kOzoneHalfWidthM = 15e3;
double ozone_cross_section_m2(double nm) {
    const double sigma = nm < 603.0 ? 75.0 / 1.1774 : 58.0 / 1.1774;
    const double t = (nm - 603.0) / sigma;
    return 5.0e-25 * std::exp(-0.5 * t * t);
}
// The observer: sea level (the dome changes little over a terrain's few kilometres).
constexpr double kObserverRadiusM = kEarthRadiusM + 1.0;

// Densities relative to sea level; ozone's per metre of its column (its vertical integral is 1).
struct Densities {
    double rayleigh = 0.0, mie = 0.0, ozone = 0.0;
};
Densities densities_at(double altitude_m) {
    const double h = std::max(altitude_m, 0.0);
    return {std::exp(float(-h / kRayleighScaleHeightM)), std::exp(float(-h / kMieScaleHeightM)),
            std::max(0.0, 1.0 - std::abs(h - kOzonePeakM) / kOzoneHalfWidthM) / kOzoneHalfWidthM};
}

// Distance from radius r along cos(zenith) mu to the top of the atmosphere; negative when the
// ray meets the ground first.
double distance_to_top(double r, double mu) {
    const double ground = r * r * (mu * mu - 1.0) + kEarthRadiusM * kEarthRadiusM;
    if (mu < 0.0 && ground >= 0.0) return -1.0;
    return -r * mu + std::sqrt(std::max(0.0, r * r * (mu * mu - 1.0) + kTopRadiusM * kTopRadiusM));
}

// Densities integrated from radius r along cos(zenith) mu to the top (which the ray must reach):
// steps dense near the start, where the density is highest (t = d u^2).
Densities optical_path(double r, double mu, int steps) {
    const double d = distance_to_top(r, mu);
    Densities sum;
    for (int k = 0; k < steps; ++k) {
        const double u = (k + 0.5) / steps;
        const double t = d * u * u;
        const double dt = 2.0 * d * u / steps;
        const double rr = std::sqrt(r * r + t * t + 2.0 * r * t * mu);
        const Densities rho = densities_at(rr - kEarthRadiusM);
        sum.rayleigh += rho.rayleigh * dt;
        sum.mie += rho.mie * dt;
        sum.ozone += rho.ozone * dt;
    }
    return sum;
}

// The integrated densities towards the sun from any point, over altitude and the sun's
// elevation there. It depends on nothing but the atmosphere's constants above, so it is made
// once and shared (immutable after construction).
class SunPathTable {
public:
    static constexpr int kAltitudes = 48;
    // Uniform in the sine of the elevation from -0.35 (-20.5 degrees): steps of 0.25 degree at
    // the horizon, where the path changes fastest, and no asin per look-up.
    static constexpr int kElevations = 541;
    static constexpr double kLowestSin = -0.35;
    static constexpr double kStepSin = 1.35 / (kElevations - 1);
    // A depth that stands for "the Earth is in the way": exp(-it) is 0 for every coefficient.
    static constexpr double kBlocked = 1e12;

    SunPathTable() : paths_(std::size_t(kAltitudes) * kElevations) {
        for (int i = 0; i < kAltitudes; ++i) {
            const double r = kEarthRadiusM + altitude_of(i);
            for (int j = 0; j < kElevations; ++j) {
                const double mu = kLowestSin + j * kStepSin;
                paths_[std::size_t(i) * kElevations + std::size_t(j)] =
                    distance_to_top(r, mu) < 0.0 ? Densities{kBlocked, kBlocked, kBlocked} : optical_path(r, mu, 96);
            }
        }
    }
    static const SunPathTable& instance() {
        static const SunPathTable table;
        return table;
    }
    // Bilinear in (sqrt of altitude, elevation).
    Densities at(double altitude_m, double sin_elevation) const {
        const double h = altitude_m > 0.0 ? std::min(altitude_m, kAtmosphereHeightM) : 0.0;  // NaN -> 0
        const double a = std::sqrt(h / kAtmosphereHeightM) * (kAltitudes - 1);
        const double e = (std::min(sin_elevation, 1.0) - kLowestSin) / kStepSin;
        if (!(e >= 0.0)) return {kBlocked, kBlocked, kBlocked};  // below the table, or NaN
        const int i = std::min(int(a), kAltitudes - 2);
        const int j = std::min(int(e), kElevations - 2);
        const double fa = std::min(a - i, 1.0), fe = std::min(e - j, 1.0);
        auto p = [&](int di, int dj) { return paths_[std::size_t(i + di) * kElevations + std::size_t(j + dj)]; };
        const double w00 = (1 - fa) * (1 - fe), w01 = (1 - fa) * fe, w10 = fa * (1 - fe), w11 = fa * fe;
        Densities out;
        out.rayleigh = w00 * p(0, 0).rayleigh + w01 * p(0, 1).rayleigh + w10 * p(1, 0).rayleigh + w11 * p(1, 1).rayleigh;
        out.mie = w00 * p(0, 0).mie + w01 * p(0, 1).mie + w10 * p(1, 0).mie + w11 * p(1, 1).mie;
        out.ozone = w00 * p(0, 0).ozone + w01 * p(0, 1).ozone + w10 * p(1, 0).ozone + w11 * p(1, 1).ozone;
        return out;
    }

private:
    static double altitude_of(int i) {
        const double v = double(i) / (kAltitudes - 1);
        return kAtmosphereHeightM * v * v;
    }
    std::vector<Densities> paths_;
};

// The dome's table: elevations dense near the horizon (e = 90 deg v^2), azimuths from the sun.
constexpr int kTableElevations = 40;
constexpr int kTableAzimuths = 12;
constexpr int kViewSteps = 32;

double wavelength_nm(int k) {
    return kSkyFirstWavelengthNm + k * kSkyWavelengthStepNm;
}

// Planck's law, up to a constant, at wavelength nm and temperature kelvin.
double black_body(double nm, double kelvin) {
    const double lambda_um = nm * 1e-3;
    return 1.0 / (std::pow(lambda_um, 5.0) * (std::exp(14387.77 / (lambda_um * kelvin)) - 1.0));
}

// The colour-matching functions integrated against the spectrum's piecewise-linear
// interpolation between the samples (held constant beyond the first and last).
std::array<glm::dvec3, kSkyWavelengths> sample_weights_xyz() {
    std::array<glm::dvec3, kSkyWavelengths> w{};
    for (double nm = 360.0; nm <= 830.0; nm += 1.0) {
        const glm::dvec3 cmf = cie_1931_color_matching(nm);
        const double pos = (nm - kSkyFirstWavelengthNm) / kSkyWavelengthStepNm;
        if (pos <= 0.0) {
            w[0] += cmf;
        } else if (pos >= kSkyWavelengths - 1) {
            w[kSkyWavelengths - 1] += cmf;
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
    const double g = kMieAsymmetry;
    const double denom = std::max(1e-9, 1.0 + g * g - 2.0 * g * cos_gamma);
    return 3.0 / (8.0 * kPi) * (1.0 - g * g) * (1.0 + cos_gamma * cos_gamma) / ((2.0 + g * g) * denom * std::sqrt(denom));
}

}  // namespace

PhysicalSky::PhysicalSky(double turbidity, double ground_albedo, const glm::dvec3& sun_direction_enu)
    : PhysicalSky(Aerosol{angstrom_beta(turbidity), 1.3}, ground_albedo, sun_direction_enu, turbidity) {}

PhysicalSky::PhysicalSky(const Aerosol& aerosol, double ground_albedo, const glm::dvec3& sun_direction_enu,
                         double turbidity)
    : turbidity_(turbidity), albedo_(ground_albedo) {
    glm::dvec3 s = sun_direction_enu;
    const double len = std::sqrt(s.x * s.x + s.y * s.y + s.z * s.z);
    s = (std::isfinite(len) && len > 0.0) ? s / len : glm::dvec3(0.0, 0.0, 1.0);
    sun_dir_ = s;
    const double h = std::hypot(s.x, s.y);
    sun_east_ = h > 1e-9 ? glm::dvec3(s.x / h, s.y / h, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
    sun_north_ = glm::dvec3(-sun_east_.y, sun_east_.x, 0.0);

    // Per wavelength: coefficients, and the extraterrestrial sun through the colour matching
    // into linear RGB, scaled so its luminance is the luminous solar constant.
    const std::array<glm::dvec3, kSkyWavelengths> cmf = sample_weights_xyz();
    double luminance_sum = 0.0;
    for (int k = 0; k < kSkyWavelengths; ++k) {
        const double nm = wavelength_nm(k);
        const double um = nm * 1e-3;
        const double mie = aerosol.beta * std::pow(um, -aerosol.alpha) / kMieScaleHeightM;
        rayleigh_[std::size_t(k)] = float(rayleigh_optical_depth(um) / kRayleighScaleHeightM);
        mie_extinction_[std::size_t(k)] = float(mie);
        mie_scattering_[std::size_t(k)] = float(kAerosolSingleScatteringAlbedo * mie);
        ozone_[std::size_t(k)] = float(ozone_cross_section_m2(nm) * kOzoneColumnPerM2);
        luminance_sum += black_body(nm, kSunTemperatureK) * cmf[std::size_t(k)].y;
    }
    for (int k = 0; k < kSkyWavelengths; ++k) {
        const glm::dvec3 xyz = cmf[std::size_t(k)] * (black_body(wavelength_nm(k), kSunTemperatureK) *
                                                      kSolarIlluminanceKlx / luminance_sum);
        weight_[std::size_t(k)] = xyz_to_linear_srgb(xyz.x, xyz.y, xyz.z);
    }

    // The sun's beam: the same atmosphere from the observer. Zero once the disc has set.
    if (std::asin(std::clamp(s.z, -1.0, 1.0)) >= -sun_.angular_radius_rad) {
        const Densities path = SunPathTable::instance().at(kObserverRadiusM - kEarthRadiusM, std::max(s.z, 0.0));
        Rgb e(0.0f);
        for (int k = 0; k < kSkyWavelengths; ++k) {
            const std::size_t kk = std::size_t(k);
            const double t = std::exp(-(rayleigh_[kk] * path.rayleigh + mie_extinction_[kk] * path.mie + ozone_[kk] * path.ozone));
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

// Single scattering along the view ray from the observer: at each step, the light of the sun
// that reached it (the sun path's transmittance) scattered towards the observer, dimmed on the
// way back (the view path's). The phase functions are the same at every step (the sun is at
// infinity), so they are left out and applied per direction.
PhysicalSky::NodeRadiance PhysicalSky::integrate(const glm::dvec3& view) const {
    const double mu = std::clamp(view.z, 0.0, 1.0);
    const double d = distance_to_top(kObserverRadiusM, mu);
    const SunPathTable& sun_paths = SunPathTable::instance();
    // The spectral loop in float: 17 exponentials a step are most of a sky's cost, and float's
    // 1e-7 is far below the table's 2% interpolation error.
    std::array<float, kSkyWavelengths> sum_r{}, sum_m{};
    Densities behind;  // integrated along the view ray up to the current step
    for (int k = 0; k < kViewSteps; ++k) {
        const double u = (k + 0.5) / kViewSteps;
        const double t = d * u * u;
        const double dt = 2.0 * d * u / kViewSteps;
        const glm::dvec3 p = glm::dvec3(0.0, 0.0, kObserverRadiusM) + view * t;
        const double r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
        const Densities rho = densities_at(r - kEarthRadiusM);
        const Densities to_sun = sun_paths.at(r - kEarthRadiusM, (p.x * sun_dir_.x + p.y * sun_dir_.y + p.z * sun_dir_.z) / r);
        const Densities here{behind.rayleigh + 0.5 * rho.rayleigh * dt, behind.mie + 0.5 * rho.mie * dt,
                             behind.ozone + 0.5 * rho.ozone * dt};
        behind.rayleigh += rho.rayleigh * dt;
        behind.mie += rho.mie * dt;
        behind.ozone += rho.ozone * dt;
        if (to_sun.rayleigh > 1e-3 * SunPathTable::kBlocked) continue;  // in the Earth's shadow
        const float path_r = float(here.rayleigh + to_sun.rayleigh);
        const float path_m = float(here.mie + to_sun.mie);
        const float path_o = float(here.ozone + to_sun.ozone);
        const float w_r = float(rho.rayleigh * dt), w_m = float(rho.mie * dt);
        for (std::size_t w = 0; w < kSkyWavelengths; ++w) {
            const float transmittance = std::exp(-(rayleigh_[w] * path_r + mie_extinction_[w] * path_m + ozone_[w] * path_o));
            sum_r[w] += transmittance * w_r;
            sum_m[w] += transmittance * w_m;
        }
    }
    NodeRadiance out;
    for (std::size_t w = 0; w < kSkyWavelengths; ++w) {
        out.rayleigh += weight_[w] * (rayleigh_[w] * sum_r[w]);
        out.mie += weight_[w] * (mie_scattering_[w] * sum_m[w]);
    }
    return out;
}

Rgb PhysicalSky::sky_radiance(const glm::dvec3& dir) const {
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
    return with_phases(n, glm::normalize(glm::dvec3(dir.x, dir.y, z)));
}

Rgb PhysicalSky::sky_radiance_integrated(const glm::dvec3& dir) const {
    const glm::dvec3 v = glm::normalize(glm::dvec3(dir.x, dir.y, std::max(dir.z, 0.0)));
    return with_phases(integrate(v), v);
}

Rgb PhysicalSky::with_phases(const NodeRadiance& n, const glm::dvec3& unit_view) const {
    const double cos_gamma = std::clamp(glm::dot(unit_view, sun_dir_), -1.0, 1.0);
    const Rgb l = n.rayleigh * static_cast<float>(rayleigh_phase(cos_gamma)) + n.mie * static_cast<float>(mie_phase(cos_gamma));
    return glm::max(l, Rgb(0.0f));
}

Rgb PhysicalSky::radiance(const glm::dvec3& dir) const {
    return dir.z > 0.0 ? sky_radiance(dir) : ground_;
}

std::string PhysicalSky::describe() const {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "clear sky (single scattering, physical), turbidity %.2f, ground albedo %.2f, zenith %.2f kcd/m2",
                  turbidity_, albedo_, luminance(sky_radiance(glm::dvec3(0.0, 0.0, 1.0))));
    return buf;
}

}  // namespace ts::light
