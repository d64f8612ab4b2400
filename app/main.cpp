// terrashade: terrain visibility and shading from real DEMs.
#include <CLI/CLI.hpp>

#include "app/bench_forward.hpp"
#include "app/command.hpp"
#include "app/interrupt_watcher.hpp"
#include "app/number_flags.hpp"
#include "app/run_command_line.hpp"

int main(int argc, char** argv) {
    // The benchmarks are their own executable (app/bench_forward.hpp).
    if (ts::app::is_bench_command(argc, argv)) return ts::app::forward_to_bench(argc, argv);
    // First, before any thread exists: every thread inherits the blocked SIGINT/SIGTERM.
    ts::app::interrupt::start();
    CLI::App root{"terrashade: shading of real terrain with log-SH visibility and sun/sky lighting", "terrashade"};
    root.require_subcommand(1);
    root.set_version_flag("--version", "terrashade 0.1.0");
    ts::app::add_info_command(root);
    ts::app::add_hillshade_command(root);
    ts::app::add_bench_placeholder(root);
    ts::app::add_visibility_command(root);
    ts::app::add_sun_command(root);
    ts::app::add_render_command(root);
    ts::app::add_relight_command(root);
    ts::app::add_spheres_command(root);
    ts::app::add_tiles_command(root);
    ts::app::add_plan_command(root);
    ts::app::add_merge_command(root);
    ts::app::add_insolation_command(root);
#ifdef TERRASHADE_HAS_GPU
    ts::app::add_devices_command(root);
    ts::app::add_fly_command(root);
#endif
    ts::app::explain_non_numbers(root);
    return ts::app::run_command_line(root, argc, argv);
}
