#pragma once
// Adaptive quality for shaded pictures (render, relight, tiles, fly --max-error E): the cheapest
// renderer settings whose predicted relative radiance error stays under E for this scene.
//
// The error measured is bench render's: the relative RMSE of the luminance against the
// ray-traced reference (docs/accuracy.md). It is mostly the transfer's low bias, which grows as
// the sun gets low, plus a horizon and sun-shadow part that grows with the relief over distance.
// So the prediction is, per setting and per fitted sun elevation,
//     relative radiance error = a + b x roughness       (roughness: mean_tan_slope)
// with a and b the upper envelope of the bench windows (times a margin), fitted by
// scripts/fit_radiance_quality.py into radiance_error_table.inc, and linear in the sun's
// elevation between fitted elevations (held at the ends). Flat ground gets the cheapest setting
// the sun allows.
#include <functional>
#include <string>
#include <vector>

namespace ts::quality {

// One row of the fitted table: a setting at one sun elevation.
struct RadianceErrorRow {
    int directions = 32;
    bool exact_sun = false;  // --sun-shadows exact instead of the sweep
    double sun_elevation_deg = 0;
    double intercept = 0;        // a
    double per_roughness = 0;    // b
};

struct RadianceSetting {
    int directions = 32;
    bool exact_sun = false;
    std::vector<RadianceErrorRow> rows;  // by rising sun elevation
};

// The settings in order of cost (cheapest first), from the fitted table.
const std::vector<RadianceSetting>& radiance_settings();

// Lowest and highest sun elevation the table was fitted at (degrees).
double lowest_fitted_elevation();
double highest_fitted_elevation();

// The predicted relative radiance error of `s` for terrain of this roughness under a sun this
// high (degrees; held at the fitted range's ends).
double predicted_radiance_error(const RadianceSetting& s, double roughness, double sun_elevation_deg);

struct RadianceScene {
    double roughness = 0;  // mean tan slope of the shaded grid (after any vertical scale)
    // The suns the pictures are lit by (a relight sequence: every frame's); the prediction is
    // the largest over them. Empty: the lowest fitted elevation (the worst case).
    std::vector<double> sun_elevations_deg;
    bool exact_sun_available = true;  // false: only the sweep settings (tiles, fly)
};

struct RadianceChoice {
    int directions = 32;
    bool exact_sun = false;
    double predicted_error = 0;
    double worst_sun_elevation_deg = 0;  // the sun the prediction came from
    bool met = true;  // false: even the finest setting is predicted above the bound
    std::string reason;  // one line: what was chosen and why
};

// The cheapest setting predicted under `max_error` for this scene; the finest one (met = false)
// when none is. With `rest_fits` (the meshes: blocker_quality.hpp), a setting must also leave a
// budget, max_error minus its prediction, that rest_fits accepts. Throws ts::InputError for
// max_error <= 0.
RadianceChoice choose_radiance(double max_error, const RadianceScene& scene,
                               const std::function<bool(double budget)>& rest_fits = {});

// The relative cost of a setting (ms for 80 x 80 texels, state and frame): the bench's times are
// roughly 60 + 2.2 D, the exact sun pass about 12 more (docs/accuracy.md).
double relative_cost(const RadianceSetting& s);

// One setting per region of a picture (the blocks of a tile level), so that flat regions get
// less work: regions of these roughnesses and area weights (any positive scale), each starting at
// the cheapest setting, upgraded greedily where the predicted mean square error falls most per
// unit of cost, until the picture's predicted RMS error, sqrt(sum w e^2 / sum w), is at most
// max_error (or every region is at the finest: met = false). Returns indices into
// radiance_settings(); the sweep settings only unless exact_sun_available.
struct RegionChoice {
    std::vector<int> setting;  // per region
    double predicted_error = 0;
    bool met = true;
};
RegionChoice choose_radiance_per_region(double max_error, const std::vector<double>& roughness,
                                        const std::vector<double>& weight, double sun_elevation_deg,
                                        bool exact_sun_available);

}  // namespace ts::quality
