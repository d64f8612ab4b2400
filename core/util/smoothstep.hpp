#pragma once
// Hermite's smooth step: 0 at or below e0, 1 at or above e1, 3t^2 - 2t^3 between. The blend of
// every material border, so classes hand over without a contour line.
#include <algorithm>

namespace ts {

inline double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

}  // namespace ts
