#pragma once
// The DEM inputs every command shares: positional files (several = one mosaic), --crop, --no-fill.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/dem/dem.hpp"
#include "core/dem/fill_voids.hpp"

namespace ts::app {

struct DemInput {
    std::vector<std::string> files;
    std::vector<double> crop;  // W,S,E,N degrees, or empty
    bool fill_voids = true;
    int fill_max_distance = ts::dem::kDefaultFillMaxDistance;  // texels; holes wider stay outside
};

// Adds `DEM...` (required), `--crop W,S,E,N` and, when with_fill_option, `--no-fill` and
// `--fill-max-distance N`.
void add_dem_input_options(CLI::App& cmd, DemInput& in, bool with_fill_option = true);

// Reads every file, mosaics them, crops, fills the holes enclosed by data (void_mask keeps the
// record; border-connected nodata and holes wider than the max distance stay NaN: outside).
// Throws ts::InputError naming the file on bad input.
ts::dem::Dem load_dem_input(const DemInput& in);

// A DEM of a single row or column has no neighbours to cast a horizon or give a slope: every
// horizon is open and the ground flat. Prints one warning line (the outputs are still written).
void warn_if_single_line(const ts::dem::Dem& dem);

// The sun lights the sea's surface, not its floor: on a DEM that holds the sea floor (its lowest
// height below render::kSeaFloorBelowM, as the colours decide) every height below 0 m becomes
// 0 m, for solar sums (insolation, tiles --style insolation). Below the surface the ESRA air
// mass took 4 km of sea as 4 km of extra atmosphere (15% too little sun at 0 N 140 W) and
// seamounts shaded the sea. Prints one note when it changes anything; returns whether it did.
bool raise_sea_floor_to_surface(ts::dem::Dem& dem);

}  // namespace ts::app
