// terrashade-bench: the measurements behind docs/ (`terrashade bench ...` runs it). Apart from
// terrashade so that building the product compiles no benchmark or study code.
#include <CLI/CLI.hpp>

#include "app/bench/bench_command.hpp"
#include "app/heap_huge_pages.hpp"
#include "app/interrupt_watcher.hpp"
#include "app/number_flags.hpp"
#include "app/run_command_line.hpp"

int main(int argc, char** argv) {
    // The heap on huge pages, as terrashade's (app/heap_huge_pages.hpp): the same costs measured.
    ts::app::reexec_with_heap_huge_pages(argv);
    // First, before any thread exists: every thread inherits the blocked SIGINT/SIGTERM.
    ts::app::interrupt::start();
    CLI::App bench{"terrashade bench: measure accuracy and speed (the data behind the charts in docs/)",
                   "terrashade bench"};
    bench.require_subcommand(1);
    ts::app::add_bench_commands(bench);
    ts::app::explain_non_numbers(bench);
    return ts::app::run_command_line(bench, argc, argv);
}
