#pragma once
// The sun's visible fraction per texel (../shared/design/METHOD.md, "treat the sun apart"): the
// part of the sun's disc above the exact horizon in the sun's azimuth, so sun shadows are crisp
// and right.
#include <string>
#include <vector>

#include "core/terrain/height_grid.hpp"
#include "core/visibility/horizon_options.hpp"

namespace ts::visibility {

// Fraction (0..1) of a disc of angular radius r centred at elevation e that lies above a flat
// horizon line at elevation h (all radians): the circular-segment area over the disc's area.
double sun_disc_visible_fraction(double horizon_rad, double sun_elevation_rad, double sun_radius_rad);

// The inverse: the horizon above the sun's centre (h - e, radians, within [-r, r]) that leaves
// `fraction` of the disc visible. What a texel darkened by other shadows (meshes, terrain
// beyond the grid) is given, so its horizon agrees with its fraction.
double horizon_above_sun_for_fraction(double fraction, double sun_radius_rad);

// How a renderer computes the sun's visible fraction each frame: `sweep` (SunShadowSweep,
// sun_sweep.hpp: shadow heights along the sweep lines, built once per grid, much faster) or
// `exact` (sun_visibility below: the reference).
enum class SunMethod { sweep, exact };
// "sweep" | "exact"; anything else throws ts::InputError naming the choices.
SunMethod parse_sun_method(const std::string& name);
std::string sun_method_name(SunMethod method);

// How far from the sun's elevation a horizon asked of the sweep is exact (and where it is
// clamped): a view that interpolates the horizon between texels finds a shadow's edge where
// the interpolated h - e crosses zero, so both sides of an edge need their true values, not
// the disc's band alone. 5 degrees: a texel beside a cliff's shadow can be several degrees from
// the sun on either side.
inline constexpr double kSunHorizonBandRad = 5.0 * 3.14159265358979323846 / 180.0;

struct SunVisibilityOptions {
    bool curvature = true;             // as HorizonOptions::curvature
    double sun_radius_rad = 0.004654;  // 0.2667 deg
    // As HorizonOptions::exact_near_field_texels, but 8 rather than 2: a shadow's rim is where
    // the sweep's interpolation between lines errs, and marching 8 texels exactly raised the
    // shadow masks' IoU against the raymarched reference from 0.969..0.981 to >= 0.994 on the
    // shared DEMs for ~1.3x the time (docs/accuracy.md).
    double near_field_texels = 8.0;
    int lines_per_texel = 1;  // as HorizonOptions::exact_lines_per_texel
    ReceiverWindow window;
    int threads = 0;
};

// The exact horizon elevation (radians) of every receiver of the window in one azimuth
// (internal phi, counter-clockwise from east), as exact_horizons computes it for its D
// azimuths; NaN for void receivers. [row * width + col] of the window.
std::vector<float> exact_horizon_in_azimuth(const terrain::HeightGrid& grid, double phi_rad,
                                            const HorizonOptions& options);

// Visible fraction of the sun disc per receiver texel; NaN for void receivers. The sun is
// given as the user sees it: azimuth clockwise from north, elevation above the horizon.
// With `horizon_above_sun`: each texel's horizon elevation less the sun's (radians), exact
// within kSunHorizonBandRad and clamped to it, as SunShadowSweep::compute gives it.
std::vector<float> sun_visibility(const terrain::HeightGrid& grid, double sun_azimuth_deg, double sun_elevation_deg,
                                  const SunVisibilityOptions& options = {},
                                  std::vector<float>* horizon_above_sun = nullptr);

}  // namespace ts::visibility
