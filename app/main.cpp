// terrashade: terrain visibility and shading from real DEMs.
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "app/command.hpp"
#include "app/job_memory.hpp"
#include "app/interrupt_watcher.hpp"
#include "app/number_flags.hpp"
#include "core/util/error.hpp"

namespace {
constexpr int kExitOk = 0;
constexpr int kExitBug = 1;
constexpr int kExitBadInput = 2;
}  // namespace

int main(int argc, char** argv) {
    // First, before any thread exists: every thread inherits the blocked SIGINT/SIGTERM.
    ts::app::interrupt::start();
    CLI::App root{"terrashade: shading of real terrain with log-SH visibility and sun/sky lighting", "terrashade"};
    root.require_subcommand(1);
    root.set_version_flag("--version", "terrashade 0.1.0");
    ts::app::add_info_command(root);
    ts::app::add_hillshade_command(root);
    ts::app::add_bench_command(root);
    ts::app::add_visibility_command(root);
    ts::app::add_sun_command(root);
    ts::app::add_render_command(root);
    ts::app::add_relight_command(root);
    ts::app::add_spheres_command(root);
    ts::app::add_tiles_command(root);
    ts::app::add_plan_command(root);
    ts::app::add_merge_command(root);
#ifdef TERRASHADE_HAS_GPU
    ts::app::add_devices_command(root);
    ts::app::add_fly_command(root);
#endif
    ts::app::explain_non_numbers(root);
    try {
        ts::app::apply_memory_limit_from_environment();
        root.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return root.exit(e) == 0 ? kExitOk : kExitBadInput;
    } catch (const CLI::CallForAllHelp& e) {
        return root.exit(e) == 0 ? kExitOk : kExitBadInput;
    } catch (const CLI::CallForVersion& e) {
        root.exit(e);
        return kExitOk;
    } catch (const CLI::ParseError& e) {
        // One line, naming the problem, then where to look.
        std::fprintf(stderr, "terrashade: %s (see --help)\n", e.what());
        return kExitBadInput;
    } catch (const ts::InputError& e) {
        std::fprintf(stderr, "terrashade: %s\n", e.what());
        return kExitBadInput;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "terrashade: out of memory\n");
        return kExitBadInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "terrashade: internal error: %s\n", e.what());
        return kExitBug;
    }
    return kExitOk;
}
