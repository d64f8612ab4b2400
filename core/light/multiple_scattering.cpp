#include "core/light/multiple_scattering.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>

#include "core/util/angles.hpp"

namespace ts::light {

namespace {

using atmosphere::Coefficients;
using atmosphere::Densities;
using atmosphere::Spectrum;
using atmosphere::kWavelengths;

constexpr double kPsiSunSineStep = (1.0 - MultipleScattering::kLowestSin) / (MultipleScattering::kSunSines - 1);
// Directions of the sphere integrals: midpoints in cos(zenith) by azimuth over the half sphere
// on one side of the sun's vertical plane (the other half mirrors it).
constexpr int kZeniths = 16;
constexpr int kAzimuths = 4;
constexpr int kSteps = 24;

double psi_altitude_of_row(int i) {
    const double v = double(i) / (MultipleScattering::kAltitudes - 1);
    return atmosphere::kHeightM * v * v;
}

// A bilinear look-up in a [row][column][wavelength] table over (sqrt of altitude up to the top
// of the atmosphere, sine of the sun's elevation from `lowest_sin` in steps of `step`): the
// four corners and their weights; false below the table (or for a NaN sine).
struct SpectralCorners {
    const float* p[4];
    float w[4];
};
bool spectral_corners(const std::vector<float>& table, int rows, int columns, double lowest_sin, double step,
                      double altitude_m, double sin_elevation, SpectralCorners& c) {
    const double h = altitude_m > 0.0 ? std::min(altitude_m, atmosphere::kHeightM) : 0.0;  // NaN -> 0
    const double a = std::sqrt(h / atmosphere::kHeightM) * (rows - 1);
    const double e = (std::min(sin_elevation, 1.0) - lowest_sin) / step;
    if (!(e >= 0.0)) return false;
    const int i = std::min(int(a), rows - 2);
    const int j = std::min(int(e), columns - 2);
    const float fa = float(std::min(a - i, 1.0)), fe = float(std::min(e - j, 1.0));
    c.p[0] = &table[(std::size_t(i) * columns + std::size_t(j)) * kWavelengths];
    c.p[1] = c.p[0] + kWavelengths;
    c.p[2] = c.p[0] + std::size_t(columns) * kWavelengths;
    c.p[3] = c.p[2] + kWavelengths;
    c.w[0] = (1 - fa) * (1 - fe), c.w[1] = (1 - fa) * fe, c.w[2] = fa * (1 - fe), c.w[3] = fa * fe;
    return true;
}

// The sun's transmittance per wavelength over (sqrt of altitude, sine of elevation), so the
// sphere integrals look it up instead of taking 17 exponentials for every sun and step.
class SunTransmittance {
public:
    static constexpr int kRows = 32;
    static constexpr int kColumns = 271;
    static constexpr double kLowestSin = -0.35;
    static constexpr double kStep = 1.35 / (kColumns - 1);

    explicit SunTransmittance(const Coefficients& c) : t_(std::size_t(kRows) * kColumns * kWavelengths) {
        const auto& paths = atmosphere::SunPathTable::instance();
        for (int i = 0; i < kRows; ++i) {
            const double v = double(i) / (kRows - 1);
            for (int j = 0; j < kColumns; ++j) {
                const Densities d = paths.at(atmosphere::kHeightM * v * v, kLowestSin + j * kStep);
                float* out = &t_[(std::size_t(i) * kColumns + std::size_t(j)) * kWavelengths];
                for (std::size_t w = 0; w < kWavelengths; ++w) {
                    out[w] = atmosphere::SunPathTable::blocked(d)
                                 ? 0.0f
                                 : std::exp(-float(c.rayleigh[w] * d.rayleigh + c.mie_extinction[w] * d.mie +
                                                   c.ozone[w] * d.ozone));
                }
            }
        }
    }
    // Adds weight x transmittance at (altitude, sine) to `sum`.
    void accumulate(double altitude_m, double sin_elevation, const float* weight, float* sum) const {
        SpectralCorners c;
        if (!spectral_corners(t_, kRows, kColumns, kLowestSin, kStep, altitude_m, sin_elevation, c)) return;
        for (std::size_t w = 0; w < kWavelengths; ++w) {
            sum[w] += weight[w] * (c.w[0] * c.p[0][w] + c.w[1] * c.p[1][w] + c.w[2] * c.p[2][w] + c.w[3] * c.p[3][w]);
        }
    }

private:
    std::vector<float> t_;
};

Coefficients delta_scaled(const Coefficients& c, double forward) {
    Coefficients s = c;
    for (std::size_t w = 0; w < kWavelengths; ++w) {
        s.mie_extinction[w] = float(c.mie_extinction[w] - forward * c.mie_scattering[w]);
        s.mie_scattering[w] = float((1.0 - forward) * c.mie_scattering[w]);
    }
    return s;
}

}  // namespace

MultipleScattering::MultipleScattering(const Coefficients& atmosphere, double ground_albedo)
    : medium_(delta_scaled(atmosphere, kForwardFraction)),
      psi_(std::size_t(kAltitudes) * kSunSines * kWavelengths, 0.0f) {
    const Coefficients& c = medium_;
    const SunTransmittance sun(c);
    const double isotropic_phase = 1.0 / (4.0 * kPi);
    const double ground_brdf = ground_albedo / kPi;
    for (int a = 0; a < kAltitudes; ++a) {
        const double r = atmosphere::kEarthRadiusM + std::min(psi_altitude_of_row(a), atmosphere::kHeightM - 1.0);
        std::vector<double> second(std::size_t(kSunSines) * kWavelengths, 0.0);  // L2 per sun and wavelength
        Spectrum transfer{};                                                        // f
        for (int iz = 0; iz < kZeniths; ++iz) {
            const double mu = -1.0 + (iz + 0.5) * 2.0 / kZeniths;
            const double ground_t = atmosphere::distance_to_ground(r, mu);
            const bool hits_ground = ground_t > 0.0;
            const double d = hits_ground ? ground_t : atmosphere::distance_to_top(r, mu);
            const double sin_theta = std::sqrt(std::max(0.0, 1.0 - mu * mu));
            for (int ia = 0; ia < kAzimuths; ++ia) {
                const double phi = kPi * (ia + 0.5) / kAzimuths;
                // Solid angle of the node, both mirrored halves, times the isotropic phase.
                const float node = float((2.0 / kZeniths) * (kPi / kAzimuths) * 2.0 * isotropic_phase);
                const double dx = sin_theta * std::cos(phi), dy = sin_theta * std::sin(phi);
                // Along the ray: where each step is, and sigma_s T dt there (independent of the sun).
                std::array<double, kSteps> px{}, pz{}, pr{};
                std::vector<float> scattered(std::size_t(kSteps) * kWavelengths);
                Densities behind;
                const double dt = d / kSteps;
                for (int k = 0; k < kSteps; ++k) {
                    const double t = (k + 0.5) * dt;
                    px[std::size_t(k)] = dx * t;
                    pz[std::size_t(k)] = r + mu * t;
                    pr[std::size_t(k)] = std::sqrt(px[std::size_t(k)] * px[std::size_t(k)] + dy * t * dy * t +
                                                   pz[std::size_t(k)] * pz[std::size_t(k)]);
                    const Densities rho = atmosphere::densities_at(pr[std::size_t(k)] - atmosphere::kEarthRadiusM);
                    const Densities here{behind.rayleigh + 0.5 * rho.rayleigh * dt, behind.mie + 0.5 * rho.mie * dt,
                                         behind.ozone + 0.5 * rho.ozone * dt};
                    behind.rayleigh += rho.rayleigh * dt;
                    behind.mie += rho.mie * dt;
                    behind.ozone += rho.ozone * dt;
                    for (std::size_t w = 0; w < kWavelengths; ++w) {
                        const float view = std::exp(-float(c.rayleigh[w] * here.rayleigh + c.mie_extinction[w] * here.mie +
                                                           c.ozone[w] * here.ozone));
                        const float s = float((c.rayleigh[w] * rho.rayleigh + c.mie_scattering[w] * rho.mie) * dt);
                        scattered[std::size_t(k) * kWavelengths + w] = s * view * node;
                        transfer[w] += s * view * node;
                    }
                }
                // The ground where the ray meets it: Lambertian, lit by the sun's beam.
                Spectrum ground_weight{};
                double gx = 0.0, gz = 0.0, gr = 1.0;
                if (hits_ground) {
                    gx = dx * d;
                    gz = r + mu * d;
                    gr = std::sqrt(gx * gx + dy * d * dy * d + gz * gz);
                    for (std::size_t w = 0; w < kWavelengths; ++w) {
                        const float view = std::exp(-float(c.rayleigh[w] * behind.rayleigh + c.mie_extinction[w] * behind.mie +
                                                           c.ozone[w] * behind.ozone));
                        ground_weight[w] = float(view * ground_brdf * node);
                        // An isotropic unit radiance lights the ground with pi, which returns the albedo.
                        transfer[w] += float(view * ground_albedo * node);
                    }
                }
                for (int js = 0; js < kSunSines; ++js) {
                    const double ss = kLowestSin + js * kPsiSunSineStep;
                    const double sc = std::sqrt(std::max(0.0, 1.0 - ss * ss));
                    Spectrum sum{};
                    for (int k = 0; k < kSteps; ++k) {
                        const std::size_t kk = std::size_t(k);
                        const double sin_here = (px[kk] * sc + pz[kk] * ss) / pr[kk];
                        sun.accumulate(pr[kk] - atmosphere::kEarthRadiusM, sin_here, &scattered[kk * kWavelengths], sum.data());
                    }
                    for (std::size_t w = 0; w < kWavelengths; ++w) sum[w] *= float(isotropic_phase);
                    if (hits_ground) {
                        const double cos_ground = (gx * sc + gz * ss) / gr;
                        if (cos_ground > 0.0) {
                            Spectrum lit = ground_weight;
                            for (float& v : lit) v *= float(cos_ground);
                            sun.accumulate(0.0, cos_ground, lit.data(), sum.data());
                        }
                    }
                    double* out = &second[std::size_t(js) * kWavelengths];
                    for (std::size_t w = 0; w < kWavelengths; ++w) out[w] += sum[w];
                }
            }
        }
        for (int js = 0; js < kSunSines; ++js) {
            for (std::size_t w = 0; w < kWavelengths; ++w) {
                psi_[(std::size_t(a) * kSunSines + std::size_t(js)) * kWavelengths + w] =
                    float(second[std::size_t(js) * kWavelengths + w] / (1.0 - std::min(double(transfer[w]), 0.99)));
            }
        }
    }
}

std::shared_ptr<const MultipleScattering> MultipleScattering::shared(const atmosphere::Aerosol& aerosol,
                                                                     double ground_albedo) {
    struct Entry {
        double beta, alpha, albedo;
        std::shared_ptr<const MultipleScattering> table;
    };
    // A few atmospheres at most per process (one per --sky); each table is 33 KB.
    static std::mutex mutex;
    static std::vector<Entry> cache;
    const std::lock_guard<std::mutex> lock(mutex);
    for (const Entry& e : cache) {
        if (e.beta == aerosol.beta && e.alpha == aerosol.alpha && e.albedo == ground_albedo) return e.table;
    }
    auto table = std::make_shared<const MultipleScattering>(atmosphere::coefficients_for(aerosol), ground_albedo);
    if (cache.size() >= 16) cache.erase(cache.begin());
    cache.push_back({aerosol.beta, aerosol.alpha, ground_albedo, table});
    return table;
}

void MultipleScattering::at(double altitude_m, double sin_sun_elevation, Spectrum& out) const {
    SpectralCorners c;
    if (!spectral_corners(psi_, kAltitudes, kSunSines, kLowestSin, kPsiSunSineStep, altitude_m, sin_sun_elevation, c)) {
        out.fill(0.0f);
        return;
    }
    for (std::size_t w = 0; w < kWavelengths; ++w)
        out[w] = c.w[0] * c.p[0][w] + c.w[1] * c.p[1][w] + c.w[2] * c.p[2][w] + c.w[3] * c.p[3][w];
}

}  // namespace ts::light
