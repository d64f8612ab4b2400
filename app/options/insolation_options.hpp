#pragma once
// The options of a clear-sky insolation sum that `insolation` and `tiles --style insolation`
// share: the dates, the atmosphere, the ground, the step of the sun's path, the gather of the
// reflected light (docs/insolation.md).
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/solar/insolation_model.hpp"
#include "core/solar/insolation_period.hpp"
#include "core/solar/terrain_reflection.hpp"

namespace ts::app {

struct InsolationArgs {
    int year = 0;  // 0: not given
    std::string from, to;
    double linke = 3.0;
    std::vector<double> linke_monthly;
    double albedo = 0.2, clear_sky_index = 1.0, step_minutes = 2.0;
    solar::TerrainReflectionSettings reflection;
    std::vector<CLI::Option*> added;  // what add_insolation_options added (any_given)
    bool any_given() const;
};

void add_insolation_options(CLI::App& cmd, InsolationArgs& a);

// The first and last day of the range (ts::InputError for what a user can get wrong).
std::pair<solar::CalendarDate, solar::CalendarDate> insolation_dates(const InsolationArgs& a);

// The days, the sky and the reflection's gather as text ("2024-01-01..2024-12-31 albedo 0.2 index 1
// step 2 linke 3,... reflection 16 64 1.3"), for the job descriptions that keep two jobs'
// outputs apart (checked as above).
std::string describe_insolation_sum(const InsolationArgs& a);

// Everything but the periods, checked (ts::InputError): Linke, albedo, index, step.
solar::InsolationSettings insolation_settings(const InsolationArgs& a);

}  // namespace ts::app
