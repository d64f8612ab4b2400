// Not a test: a Monte Carlo path tracer of the physical sky's atmosphere, the reference that
// scripts/sky_path_traced_reference.sh stores for physical_sky_test.cpp. It shares only the
// scene with the code under test (atmosphere.hpp's radii, profiles and coefficients): light of
// one wavelength followed backwards from an observer at sea level through any number of
// scatterings (delta tracking in the spherical shell; Rayleigh's and Cornette-Shanks' phase
// functions; a Lambertian ground), with the sun's transmittance integrated towards it at every
// scattering (next-event estimation). Radiance is per unit of extraterrestrial irradiance.
//   sky_path_tracer WAVELENGTH_INDEX TURBIDITY ALBEDO PATHS > OUT.csv
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/light/atmosphere.hpp"
#include "core/light/sun_transmittance.hpp"
#include "core/util/angles.hpp"

namespace {

namespace atm = ts::light::atmosphere;
using glm::dvec3;
using ts::kPi;

struct Medium {
    double rayleigh, mie_scattering, mie_extinction, ozone;  // at sea level / per ozone column
    double majorant;
};

struct Local {
    double rayleigh, mie_scattering, extinction;
};

Local at(const Medium& m, const dvec3& p) {
    const atm::Densities rho = atm::densities_at(glm::length(p) - atm::kEarthRadiusM);
    const double r = m.rayleigh * rho.rayleigh, ms = m.mie_scattering * rho.mie;
    return {r, ms, r + m.mie_extinction * rho.mie + m.ozone * rho.ozone};
}

// Distance along unit d from p to the sphere of radius `radius`, the nearer positive root when
// `first`, else the farther; -1 when none.
double to_sphere(const dvec3& p, const dvec3& d, double radius, bool first) {
    const double b = glm::dot(p, d), c = glm::dot(p, p) - radius * radius;
    const double disc = b * b - c;
    if (disc < 0.0) return -1.0;
    const double s = std::sqrt(disc);
    const double t0 = -b - s, t1 = -b + s;
    if (first) return t0 > 1e-6 ? t0 : (t1 > 1e-6 ? t1 : -1.0);
    return t1 > 1e-6 ? t1 : -1.0;
}

double sun_transmittance(const Medium& m, const dvec3& p, const dvec3& sun) {
    if (to_sphere(p, sun, atm::kEarthRadiusM, true) > 0.0) return 0.0;
    const double d = to_sphere(p, sun, atm::kTopRadiusM, false);
    if (d <= 0.0) return 1.0;
    constexpr int kSteps = 400;
    double tau = 0.0;
    for (int k = 0; k < kSteps; ++k) {
        const double u = (k + 0.5) / kSteps;
        tau += at(m, p + sun * (d * u * u)).extinction * 2.0 * d * u / kSteps;
    }
    return std::exp(-tau);
}

double rayleigh_phase(double c) {
    return 3.0 / (16.0 * kPi) * (1.0 + c * c);
}
double cornette_shanks(double c) {
    const double g = atm::kMieAsymmetry;
    const double den = 1.0 + g * g - 2.0 * g * c;
    return 3.0 / (8.0 * kPi) * (1.0 - g * g) * (1.0 + c * c) / ((2.0 + g * g) * den * std::sqrt(den));
}
double henyey_greenstein(double c) {
    const double g = atm::kMieAsymmetry;
    const double den = 1.0 + g * g - 2.0 * g * c;
    return (1.0 - g * g) / (4.0 * kPi * den * std::sqrt(den));
}

// A unit vector at cosine c from `axis`, uniformly around it.
dvec3 around(const dvec3& axis, double c, double phi) {
    const dvec3 t = std::abs(axis.z) < 0.9 ? glm::normalize(glm::cross(axis, dvec3(0, 0, 1)))
                                           : glm::normalize(glm::cross(axis, dvec3(1, 0, 0)));
    const dvec3 b = glm::cross(axis, t);
    const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    return axis * c + t * (s * std::cos(phi)) + b * (s * std::sin(phi));
}

struct Estimate {
    double single = 0.0, total = 0.0, total_sq = 0.0;
};

class Tracer {
public:
    Tracer(const Medium& m, double albedo, const dvec3& sun, unsigned seed) : m_(m), albedo_(albedo), sun_(sun), rng_(seed) {}

    // One path's radiance arriving at `origin` from direction `view`: (first order, all orders).
    std::pair<double, double> path(dvec3 x, dvec3 w) {
        double weight = 1.0, single = 0.0, total = 0.0;
        for (int order = 1; order <= 60; ++order) {
            const double ground = to_sphere(x, w, atm::kEarthRadiusM, true);
            const double top = to_sphere(x, w, atm::kTopRadiusM, false);
            const double exit = ground > 0.0 ? ground : top;
            if (exit <= 0.0) break;
            double t = 0.0;
            bool collided = false;
            Local here{};
            for (;;) {
                t -= std::log(1.0 - uniform()) / m_.majorant;
                if (t >= exit) break;
                here = at(m_, x + w * t);
                if (uniform() * m_.majorant < here.extinction) {
                    collided = true;
                    break;
                }
            }
            dvec3 next;
            if (collided) {
                x = x + w * t;
                const double scattering = here.rayleigh + here.mie_scattering;
                weight *= scattering / here.extinction;
                const bool mie = uniform() * scattering < here.mie_scattering;
                const double c = glm::dot(w, sun_);
                const double nee = weight * (mie ? cornette_shanks(c) : rayleigh_phase(c)) * sun_transmittance(m_, x, sun_);
                total += nee;
                if (order == 1) single += nee;
                next = mie ? sample_mie(w, weight) : sample_rayleigh(w);
            } else if (ground > 0.0) {
                x = x + w * ground;
                const dvec3 n = glm::normalize(x);
                const double cos_sun = glm::dot(n, sun_);
                if (cos_sun > 0.0) {
                    const double nee = weight * albedo_ / kPi * cos_sun * sun_transmittance(m_, x + n * 0.01, sun_);
                    total += nee;
                    if (order == 1) single += nee;
                }
                weight *= albedo_;
                x += n * 0.01;
                next = around(n, std::sqrt(uniform()), 2.0 * kPi * uniform());
            } else {
                break;  // out of the atmosphere
            }
            w = next;
            if (order > 3) {  // Russian roulette keeps the estimate unbiased
                const double keep = std::min(1.0, weight * 4.0);
                if (uniform() >= keep) break;
                weight /= keep;
            }
        }
        return {single, total};
    }

    Estimate radiance(const dvec3& view, int paths) {
        Estimate e;
        const dvec3 origin(0.0, 0.0, atm::kEarthRadiusM + 1.0);
        for (int i = 0; i < paths; ++i) {
            const auto [s, l] = path(origin, view);
            e.single += s;
            e.total += l;
            e.total_sq += l * l;
        }
        return e;
    }

    // Irradiance from the sky on level ground: cosine-weighted directions, E = pi E[L].
    Estimate horizontal_irradiance(int paths) {
        Estimate e;
        const dvec3 origin(0.0, 0.0, atm::kEarthRadiusM + 1.0);
        for (int i = 0; i < paths; ++i) {
            const dvec3 v = around(dvec3(0, 0, 1), std::sqrt(uniform()), 2.0 * kPi * uniform());
            const auto [s, l] = path(origin, v);
            e.single += kPi * s;
            e.total += kPi * l;
            e.total_sq += kPi * l * kPi * l;
        }
        return e;
    }

private:
    double uniform() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }
    dvec3 sample_rayleigh(const dvec3& w) {
        for (;;) {
            const double c = 2.0 * uniform() - 1.0;
            if (uniform() * 2.0 <= 1.0 + c * c) return around(w, c, 2.0 * kPi * uniform());
        }
    }
    // Henyey-Greenstein with the same asymmetry, weighted by Cornette-Shanks / HG.
    dvec3 sample_mie(const dvec3& w, double& weight) {
        const double g = atm::kMieAsymmetry;
        const double q = (1.0 - g * g) / (1.0 - g + 2.0 * g * uniform());
        const double c = std::clamp((1.0 + g * g - q * q) / (2.0 * g), -1.0, 1.0);
        weight *= cornette_shanks(c) / henyey_greenstein(c);
        return around(w, c, 2.0 * kPi * uniform());
    }
    Medium m_;
    double albedo_;
    dvec3 sun_;
    std::mt19937_64 rng_;
};

dvec3 direction(double elevation_deg, double azimuth_from_sun_deg) {
    const double e = elevation_deg * kPi / 180.0, a = azimuth_from_sun_deg * kPi / 180.0;
    return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 5) {
        std::fprintf(stderr, "usage: sky_path_tracer WAVELENGTH_INDEX TURBIDITY ALBEDO PATHS\n");
        return 2;
    }
    const int k = std::atoi(argv[1]);
    const double turbidity = std::atof(argv[2]), albedo = std::atof(argv[3]);
    const int paths = std::atoi(argv[4]);
    if (k < 0 || k >= atm::kWavelengths || paths <= 0) return 2;
    const atm::Coefficients c = atm::coefficients_for({ts::light::angstrom_beta(turbidity), 1.3});
    const std::size_t kk = std::size_t(k);
    Medium m{c.rayleigh[kk], c.mie_scattering[kk], c.mie_extinction[kk], c.ozone[kk], 0.0};
    // The ozone layer's density peaks at 1/15 km per metre of its column.
    m.majorant = m.rayleigh + m.mie_extinction + m.ozone / 15e3;
    std::printf("# sky_path_tracer %d %g %g %d: wavelength %g nm\n", k, turbidity, albedo, paths, atm::wavelength_nm(k));
    std::printf("sun_elevation,view_elevation,azimuth_from_sun,single,total,total_stderr\n");
    unsigned seed = 1;
    for (double sun_el : {2.0, 10.0, 30.0, 60.0}) {
        const dvec3 sun = direction(sun_el, 0.0);
        auto row = [&](double view_el, double az, const Estimate& e, int n) {
            const double mean = e.total / n;
            const double var = std::max(0.0, e.total_sq / n - mean * mean);
            std::printf("%g,%g,%g,%.6e,%.6e,%.3e\n", sun_el, view_el, az, e.single / n, mean, std::sqrt(var / n));
            std::fflush(stdout);
        };
        // The zenith, the dome at 90 degrees from the sun, low beside and opposite it, 30 and
        // 5 and 10 degrees from it (the aureole) along its vertical.
        for (const auto& [el, az] : {std::pair{90.0, 0.0}, {30.0, 90.0}, {5.0, 90.0}, {5.0, 180.0}, {15.0, 30.0},
                                     {sun_el + 5.0, 0.0}, {sun_el + 10.0, 0.0}}) {
            Tracer tracer(m, albedo, sun, seed++);
            row(el, az, tracer.radiance(direction(el, az), paths), paths);
        }
        Tracer tracer(m, albedo, sun, seed++);
        row(-90.0, 0.0, tracer.horizontal_irradiance(paths), paths);  // -90: the horizontal irradiance
    }
    return 0;
}
