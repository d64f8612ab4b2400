#pragma once
// What `--style insolation` colours: one quantity of the clear-sky insolation summed over a
// range of days (core/solar), through a colour ramp whose ends are fixed for the whole job so
// that every tile and zoom agree (docs/tiles.md, docs/insolation.md).
#include <memory>
#include <string>

#include "core/solar/insolation_model.hpp"
#include "core/solar/terrain_reflection.hpp"

namespace ts::tiles {

struct TileInsolation {
    // The sun of the range, built once for the whole DEM's latitudes and heights and shared by
    // every zoom and block.
    std::shared_ptr<const solar::InsolationModel> model;
    int quantity = solar::kGlobal;  // solar::Quantity, summed over the model's periods
    float lo = 0, hi = 1;           // the ramp's ends, in the quantity's unit
    std::string describe;           // what changes the tiles' bytes (the job file compares it)
    // The reflected light's gather (its radius stays within a block's 256-texel halo).
    solar::TerrainReflectionSettings reflection;
};

// "global", "beam", "diffuse", "reflected", "sun-hours": what users call solar::Quantity q.
const char* insolation_quantity_name(int quantity);

// The quantity an open horizontal plane at the model's middle latitude band and lowest level
// gets over the range: the scale the default ramp is set by (default_insolation_ramp).
double open_flat_insolation(const solar::InsolationModel& model, int quantity);

// The default ramp's ends as fractions of open flat ground's value (open_flat_insolation):
// energies from steep north faces (~0.4) to steep south faces (~1.3 at mid latitudes); hours of
// sun from none to all of the flat's; reflected light (0 on open flat ground) up to 0.3 of the
// flat's global times the albedo, what the deepest valleys get.
struct RampEnds {
    float lo, hi;
};
RampEnds default_insolation_ramp(const solar::InsolationModel& model, int quantity);

}  // namespace ts::tiles
