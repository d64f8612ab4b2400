#pragma once
// --sky-light and --sky-sectors, one declaration for every command that lights the terrain
// (render, relight, tiles, fly): the sky's light over each texel's horizons or through SH
// (core/render/horizon_sky_light.hpp).
#include <string>

#include <CLI/CLI.hpp>

#include "core/render/horizon_sky_light.hpp"

namespace ts::app {

struct SkyLightArgs {
    std::string mode = "horizons";  // horizons | sh
    int sectors = render::SkyLightSettings{}.sectors;
};

void add_sky_light_options(CLI::App& cmd, SkyLightArgs& args);

// The settings (render::Scene takes sh for the log-SH terrain transfer, which has no horizons
// to integrate over).
render::SkyLightSettings sky_light_settings(const SkyLightArgs& args);

}  // namespace ts::app
