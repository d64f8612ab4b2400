#pragma once
// The subcommands of `terrashade bench`, the commands of the terrashade-bench executable
// (bench_main.cpp; terrashade forwards `bench ...` to it, app/bench_forward.hpp). Each lives in
// its own file of app/bench/ and is added by add_bench_commands (bench_command.cpp).
#include <CLI/CLI.hpp>

namespace ts::app {

// Every bench subcommand (sh, visibility, render, ...), added to `bench`, the executable's root.
void add_bench_commands(CLI::App& bench);

// `terrashade bench visibility` (bench_visibility_command.cpp): horizon methods against the
// raymarch reference, and SAGA.
void add_bench_visibility_command(CLI::App& bench);
// `terrashade bench insolation` (bench_insolation_command.cpp): insolation against GRASS r.sun and
// SAGA, time and beam agreement.
void add_bench_insolation_command(CLI::App& bench);
// `terrashade bench relight` (bench_relight_command.cpp): relighting throughput.
void add_bench_relight_command(CLI::App& bench);
// `terrashade bench render` (bench_render_command.cpp): the renderer against the ray-traced reference.
void add_bench_render_command(CLI::App& bench);
// `terrashade bench transfer` (bench_transfer_command.cpp): exp + relight, CPU vs GPU.
void add_bench_transfer_command(CLI::App& bench);
// `terrashade bench sun` (bench_sun_command.cpp): sun visibility, sweep vs exact.
void add_bench_sun_command(CLI::App& bench);
// `terrashade bench spheres` (bench_spheres_command.cpp): sphere decomposition vs count.
void add_bench_spheres_command(CLI::App& bench);
// Mesh blockers against the ray-traced triangles; throughput; a moving aircraft.
void add_bench_blockers_command(CLI::App& bench);
// `terrashade bench tiles` (bench_tiles_command.cpp): tiles/s per style, and gdaldem + gdal2tiles.
void add_bench_tiles_command(CLI::App& bench);
// `terrashade bench fly` (bench_fly_command.cpp; GPU build only): flythrough fps and LOD figures.
void add_bench_fly_command(CLI::App& bench);
// `terrashade bench dem` (bench_dem_command.cpp): the synthetic mosaic written as a GeoTIFF, band by band.
void add_bench_dem_command(CLI::App& bench);
// `terrashade bench bounce` (bench_bounce_command.cpp): the bounced light's knobs, cost against
// the error on a crop Blender Cycles rendered.
void add_bench_bounce_command(CLI::App& bench);
// bench report: every knob's time and error in one CSV (bench_report_command.cpp).
void add_bench_report_command(CLI::App& bench);

}  // namespace ts::app
