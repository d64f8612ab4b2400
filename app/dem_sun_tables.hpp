#pragma once
// The period's sun for a whole DEM (core/solar/insolation_model.hpp), built once: the clock of
// days and months at the DEM's centre, each texel's latitude, and the tables over the DEM's
// latitudes and heights, coarsened (with a note) when a DEM spans too many to keep in memory.
// `insolation` sums it per texel; `tiles --style insolation` shares it between every zoom.
#include <memory>
#include <vector>

#include "core/dem/dem.hpp"
#include "core/solar/insolation_model.hpp"
#include "core/solar/insolation_period.hpp"

namespace ts::app {

struct DemSunTables {
    std::vector<float> latitude;  // per texel of the DEM, degrees
    std::shared_ptr<const solar::InsolationModel> model;
    solar::InsolationSettings settings;  // with the periods and the clock
    double seconds = 0;                  // building the tables
};

// settings: all but the periods and the clock, which come from [first, last] split by `split`
// on the mean solar clock of the DEM's centre. Throws ts::InputError when the DEM's CRS gives no
// longitude and latitude.
DemSunTables build_dem_sun_tables(const dem::Dem& dem, solar::InsolationSettings settings,
                                  const solar::CalendarDate& first, const solar::CalendarDate& last,
                                  solar::PeriodSplit split, double band_step_deg, double level_step_m);

}  // namespace ts::app
