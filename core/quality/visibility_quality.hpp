#pragma once
// Adaptive quality for the sky view factor (visibility --max-error E): the cheapest horizon
// settings whose predicted svf RMSE stays under E for this terrain.
//
// The prediction: svf RMSE = c(setting) x roughness, with roughness the mean tangent of the
// slope over the receivers (relief over distance: the steeper the ground, the larger and the
// faster-varying its horizons, and the more azimuths and near field it needs), and c per
// setting the largest ratio measured on the shared DEMs by `bench visibility` (times a margin),
// fitted by scripts/fit_visibility_quality.py into visibility_error_table.inc. Flat ground
// gets the cheapest setting.
#include <string>

#include "core/terrain/height_grid.hpp"

namespace ts::quality {

// Mean over valid texels (window col0, row0, width x height; width -1 = to the edge) of
// |grad z| from central differences with each row's true spacing; 0 for a grid of 1 x 1 or
// with no valid neighbours.
double mean_tan_slope(const terrain::HeightGrid& grid, int col0 = 0, int row0 = 0, int width = -1, int height = -1);

struct VisibilitySetting {
    int directions = 32;
    double near_field_texels = 2.0;
    double error_per_roughness = 0;  // c: predicted svf RMSE per unit of mean tan slope
};

struct VisibilityChoice {
    VisibilitySetting setting;
    double roughness = 0;
    double predicted_error = 0;
    bool met = true;  // false: even the finest setting is predicted above the bound
    std::string reason;  // one line: what was chosen and why
};

// The settings in order of cost (cheapest first), from the fitted table.
const std::vector<VisibilitySetting>& visibility_settings();

// The cheapest setting predicted under `max_error` for terrain of this roughness; the finest
// one (met = false) when none is. Throws ts::InputError for max_error <= 0.
VisibilityChoice choose_visibility(double max_error, double roughness);

}  // namespace ts::quality
