#include "core/material/microfacet.hpp"

#include <cmath>

#include "core/util/angles.hpp"

namespace ts::material {
namespace {
}

double beckmann_d(double cos_h, double m) {
    if (cos_h <= 0.0) return 0.0;
    const double c2 = cos_h * cos_h;
    const double tan2 = (1.0 - c2) / c2;
    return std::exp(-tan2 / (m * m)) / (kPi * m * m * c2 * c2);
}

double ggx_d(double cos_h, double alpha) {
    if (cos_h <= 0.0) return 0.0;
    const double c2 = cos_h * cos_h;
    const double tan2 = (1.0 - c2) / c2;
    const double a2 = alpha * alpha;
    const double d = a2 + tan2;
    return a2 / (kPi * c2 * c2 * d * d);
}

double smith_g1_beckmann(double cos_v, double m) {
    if (cos_v <= 0.0) return 0.0;
    if (cos_v >= 1.0) return 1.0;
    const double tan_v = std::sqrt(1.0 - cos_v * cos_v) / cos_v;
    const double a = 1.0 / (m * tan_v);
    const double lambda = 0.5 * (std::erf(a) - 1.0) + std::exp(-a * a) / (2.0 * a * std::sqrt(kPi));
    return 1.0 / (1.0 + lambda);
}

double smith_g1_ggx(double cos_v, double alpha) {
    if (cos_v <= 0.0) return 0.0;
    const double tan2 = (1.0 - cos_v * cos_v) / (cos_v * cos_v);
    return 2.0 / (1.0 + std::sqrt(1.0 + alpha * alpha * tan2));
}

double vgroove_g(double n_h, double n_i, double n_o, double o_h) {
    if (o_h <= 0.0) return 0.0;
    const double g = std::fmin(2.0 * n_h * n_o / o_h, 2.0 * n_h * n_i / o_h);
    return std::fmin(1.0, std::fmax(0.0, g));
}

}  // namespace ts::material
