#pragma once
// The gather's weights from an elevation, shared by its scalar march (terrain_gather.cpp) and
// its chunk march (terrain_gather_chunk.cpp). Internal to core/visibility.
#include <cmath>

#include "core/util/angles.hpp"
#include "core/visibility/terrain_gather.hpp"

namespace ts::visibility::gather_detail {

// The march stops once its maximum is this close below the exact horizon (0.25 degree).
constexpr double kHorizonReachedRad = 0.0043633;

// F(h) (sky_above) from h's tangent (no trig: cos^2 = 1 / (1 + t^2), sin 2h = 2t / (1 + t^2)).
inline double weight_above(double h, double tan_h, double a, double nz) {
    const double c2 = 1.0 / (1.0 + tan_h * tan_h);
    return sky_above(h, 2 * tan_h * c2, c2, a, nz);
}

// F at the exact horizon h in [-pi/2, pi/2], from sin(2h) and cos(2h) by short Taylor series on
// [-pi/2, pi/2] after reduction (errors below 4e-6, far under the sectors' discretisation):
// libm's tan here took a tenth of the gather's time in a profile.
inline double weight_above_horizon(double h, double a, double nz) {
    double x = 2 * h, flip = 1;
    if (x > kPi / 2) x = kPi - x, flip = -1;
    if (x < -kPi / 2) x = -kPi - x, flip = -1;
    const double x2 = x * x;
    const double sin2h = x * (1 + x2 * (-1.0 / 6 + x2 * (1.0 / 120 + x2 * (-1.0 / 5040 + x2 / 362880))));
    const double cos2h =
        flip * (1 + x2 * (-0.5 + x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320 - x2 / 3628800)))));
    return sky_above(h, sin2h, (1 + cos2h) / 2, a, nz);
}

}  // namespace ts::visibility::gather_detail
