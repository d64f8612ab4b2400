#pragma once
// Each subcommand lives in its own file and registers itself on the root CLI11 app.
// A command reports bad usage or input by throwing ts::InputError (exit 2, one line on
// stderr); it returns normally on success (exit 0).
#include <CLI/CLI.hpp>

namespace ts::app {

void add_info_command(CLI::App& root);
void add_hillshade_command(CLI::App& root);
void add_visibility_command(CLI::App& root);
// Only in a GPU build (TERRASHADE_HAS_GPU): the Vulkan devices and a compute self-test.
void add_devices_command(CLI::App& root);
// `terrashade sun`: the sun's position at a time and place (app/sun_command.cpp).
void add_sun_command(CLI::App& root);

// `terrashade render` and `terrashade relight` (app/render_command.cpp, app/relight_command.cpp).
void add_render_command(CLI::App& root);
void add_relight_command(CLI::App& root);
// `terrashade tiles`: Web Mercator map tiles, XYZ or MBTiles (app/tiles_command.cpp).
void add_tiles_command(CLI::App& root);

// `terrashade plan` (the work, shards and storage of a tiles or relight job) and `terrashade
// merge` (shards into one output): app/plan_command.cpp, app/merge_command.cpp, docs/scale.md.
void add_plan_command(CLI::App& root);
void add_merge_command(CLI::App& root);

// `terrashade spheres`: the bounding sphere decomposition of a mesh (app/spheres_command.cpp).
void add_spheres_command(CLI::App& root);

// `terrashade insolation`: clear-sky irradiation and hours of sun per texel (app/insolation_command.cpp).
void add_insolation_command(CLI::App& root);

// `terrashade fly`: the flythrough window or its frames offscreen (app/fly_command.cpp; GPU build only).
void add_fly_command(CLI::App& root);

}  // namespace ts::app
