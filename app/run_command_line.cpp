#include "app/run_command_line.hpp"

#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "app/exit_codes.hpp"
#include "app/job_memory.hpp"
#include "app/options/quantity_flags.hpp"
#include "core/util/error.hpp"
#include "core/util/temp_files.hpp"

namespace ts::app {
namespace {

// "render", "bench transfer": the subcommands parsed, for the flags of their quantities.
std::string command_path(const CLI::App& root) {
    std::string path;
    for (const CLI::App* app = &root;;) {
        const auto subs = app->get_subcommands();
        if (subs.empty()) return path;
        app = subs.front();
        path += (path.empty() ? "" : " ") + app->get_name();
    }
}
// A command that failed leaves nothing behind: the temporaries it had in flight, and an output
// folder it created that holds nothing (or only its job file), go as after an interrupt.
int failed(int code) {
    temp_files::hold_for_exit();
    temp_files::remove_held();
    return code;
}
}  // namespace

int run_command_line(CLI::App& root, int argc, char** argv) {
    try {
        apply_memory_limit_from_environment();
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
        return failed(kExitBadInput);
    } catch (const ts::OccupiedOutputError& e) {
        std::fprintf(stderr, "terrashade: %s\n", flag_message(e).c_str());
        return failed(kExitBadInput);
    } catch (const ts::QuantityError& e) {
        // core named the quantity; the user reads the flag they typed for it.
        std::fprintf(stderr, "terrashade: %s\n", flag_message(e, command_path(root)).c_str());
        return failed(kExitBadInput);
    } catch (const ts::InputError& e) {
        std::fprintf(stderr, "terrashade: %s\n", e.what());
        return failed(kExitBadInput);
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "terrashade: out of memory\n");
        return failed(kExitBadInput);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "terrashade: internal error: %s\n", e.what());
        return failed(kExitBug);
    }
    return kExitOk;
}

}  // namespace ts::app
