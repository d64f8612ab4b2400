#pragma once
// Sky view factor and visible sky fraction of a horizontal receiver from its horizons.
//
// With sigma(phi) the horizon elevation, clamped at 0 (only the upper hemisphere counts), and
// theta the zenith angle:
//   svf         = (1/pi)  int_0^2pi int_0^(pi/2 - sigma) cos(theta) sin(theta) dtheta dphi
//               = (1/2pi) int_0^2pi cos^2(sigma(phi)) dphi
//   sky_visible = (1/2pi) int_0^2pi int_0^(pi/2 - sigma) sin(theta) dtheta dphi
//               = 1 - (1/2pi) int_0^2pi sin(sigma(phi)) dphi
// Between two computed azimuths sigma is interpolated linearly in phi ("linear" wedges),
// which integrates in closed form (docs/visibility.md); "constant" wedges hold each
// horizon over its own 2 pi / D sector, as GIS tools do, for comparison.
#include <string_view>
#include <vector>

#include "core/visibility/horizon_set.hpp"

namespace ts::visibility {

enum class WedgeRule { linear, constant };

// Mean of cos^2(max(0, sigma)) and of sin(max(0, sigma)) for sigma linear from a to b.
double wedge_mean_cos2(double a, double b);
double wedge_mean_sin(double a, double b);

// For one receiver's D horizons (radians, internal azimuth order).
double sky_view_factor(const float* horizons, int directions, std::size_t stride, WedgeRule rule = WedgeRule::linear);
double sky_visible_fraction(const float* horizons, int directions, std::size_t stride,
                            WedgeRule rule = WedgeRule::linear);

// Per texel of the set; NaN where the horizons are NaN (void receivers). Linear wedges run
// through visibility_products (one vectorised pass; use it directly for several products).
std::vector<float> svf_raster(const HorizonSet& set, WedgeRule rule = WedgeRule::linear, int threads = 0);
std::vector<float> sky_visible_raster(const HorizonSet& set, WedgeRule rule = WedgeRule::linear, int threads = 0);

}  // namespace ts::visibility
