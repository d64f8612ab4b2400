#include "app/terrashade_main.hpp"

#include <CLI/CLI.hpp>

#include "app/bench_forward.hpp"
#include "app/command.hpp"
#include "app/heap_huge_pages.hpp"
#include "app/interrupt_watcher.hpp"
#include "app/number_flags.hpp"
#include "app/run_command_line.hpp"

namespace ts::app {

int terrashade_main(int argc, char** argv) {
    // First of all: the heap on huge pages (app/heap_huge_pages.hpp); returns unless it re-executes.
    reexec_with_heap_huge_pages(argv);
    // The benchmarks are their own executable (app/bench_forward.hpp).
    if (is_bench_command(argc, argv)) return forward_to_bench(argc, argv);
    // First, before any thread exists: every thread inherits the blocked SIGINT/SIGTERM.
    interrupt::start();
    CLI::App root{"terrashade: shading of real terrain with log-SH visibility and sun/sky lighting", "terrashade"};
    root.require_subcommand(1);
    root.set_version_flag("--version", "terrashade 0.1.0");
    add_info_command(root);
    add_hillshade_command(root);
    add_bench_placeholder(root);
    add_visibility_command(root);
    add_sun_command(root);
    add_render_command(root);
    add_relight_command(root);
    add_spheres_command(root);
    add_tiles_command(root);
    add_plan_command(root);
    add_merge_command(root);
    add_insolation_command(root);
#ifdef TERRASHADE_HAS_GPU
    add_devices_command(root);
    add_fly_command(root);
#endif
    explain_non_numbers(root);
    return run_command_line(root, argc, argv);
}

}  // namespace ts::app
