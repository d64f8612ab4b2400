#pragma once
// log-SH visibility per texel from its D horizons (the slides' step 1), and its exponential.
//
// Each azimuth slice's log-visibility is log_eps below the horizon and 0 above; the slices are
// blended linearly across azimuth and projected to 16 log-SH coefficients: the exact
// closed-form integrals of sh::SliceProjector::project_horizons, computed for all texels by
// visibility_products (one vectorised pass; its double sums are rounded to float once).
// exp_sh_raster then turns them into visibility SH with the chosen sh::ExpMethod.
#include <array>
#include <span>
#include <vector>

#include "core/sh/exp_method.hpp"
#include "core/visibility/horizon_set.hpp"

namespace ts::visibility {

// log(0.1), the CLI's --log-eps default. For terrain horizons (half the sphere and more at the
// floor) the order-4 log function is large and sharp with smaller floors, and every approximate
// exponential then strays far from the exact one: the visible fraction under a flat horizon
// comes out 0.38 with eps = 0.001 and hybrid (exact exp: 0.51), 0.51 with eps = 0.1
// (docs/visibility.md has the table).
constexpr float kDefaultVisibilityLogEps = -2.302585092994046f;

// Band-sequential 16 x (width*height): coefficient i (i = l*l + l + m) of texel t at
// [i * texels + t]. NaN for void receivers. Needs D >= 4.
std::vector<float> log_sh_raster(const HorizonSet& set, float log_eps = kDefaultVisibilityLogEps, int threads = 0);

// The log-SH of a level texel with nothing above its own plane: every one of D horizons at 0.
// What a terrain texel's transfer is when open (the band correction's reference).
std::array<float, 16> level_log_visibility(int directions, float log_eps = kDefaultVisibilityLogEps);

// exp of every texel's log-SH (same layout), with the chosen method's default options.
std::vector<float> exp_sh_raster(std::span<const float> log_sh, std::size_t texels, sh::ExpMethod method,
                                 int threads = 0);

}  // namespace ts::visibility
