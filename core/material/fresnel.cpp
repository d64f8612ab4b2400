#include "core/material/fresnel.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace ts::material {

double fresnel_dielectric(double cos_i, double eta_i, double eta_t) {
    cos_i = std::clamp(cos_i, 0.0, 1.0);
    const double sin_i2 = 1.0 - cos_i * cos_i;
    const double sin_t2 = (eta_i / eta_t) * (eta_i / eta_t) * sin_i2;
    if (sin_t2 >= 1.0) return 1.0;  // total internal reflection
    const double cos_t = std::sqrt(1.0 - sin_t2);
    const double r_par = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
    const double r_perp = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
    return 0.5 * (r_par * r_par + r_perp * r_perp);
}

double fresnel_conductor(double cos_i, double eta, double k) {
    cos_i = std::clamp(cos_i, 0.0, 1.0);
    const std::complex<double> n(eta, k);
    const double sin_i2 = 1.0 - cos_i * cos_i;
    const std::complex<double> cos_t = std::sqrt(1.0 - sin_i2 / (n * n));
    const std::complex<double> r_perp = (cos_i - n * cos_t) / (cos_i + n * cos_t);
    const std::complex<double> r_par = (n * cos_i - cos_t) / (n * cos_i + cos_t);
    return 0.5 * (std::norm(r_par) + std::norm(r_perp));
}

double fresnel_conductor_lecture(double cos_i, double eta, double k) {
    cos_i = std::clamp(cos_i, 0.0, 1.0);
    const double a = eta * eta + k * k;
    const double c2 = cos_i * cos_i;
    const double r_par2 = (a * c2 - 2.0 * eta * cos_i + 1.0) / (a * c2 + 2.0 * eta * cos_i + 1.0);
    const double r_perp2 = (a - 2.0 * eta * cos_i + c2) / (a + 2.0 * eta * cos_i + c2);
    return 0.5 * (r_par2 + r_perp2);
}

double fresnel_schlick(double cos_i, double f0) {
    const double m = 1.0 - std::clamp(cos_i, 0.0, 1.0);
    const double m2 = m * m;
    return f0 + (1.0 - f0) * m2 * m2 * m;
}

double fresnel_f0(double eta_i, double eta_t) {
    const double r = (eta_t - eta_i) / (eta_t + eta_i);
    return r * r;
}

}  // namespace ts::material
