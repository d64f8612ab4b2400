#pragma once
// The one way a terrashade executable (terrashade, terrashade-bench) parses its command line and
// turns errors into exit codes: 0 done, 1 a bug (internal error), 2 bad usage or input the user
// can fix (one line on stderr, ts::InputError or a CLI11 parse error).
#include <CLI/CLI.hpp>

namespace ts::app {

// Applies TERRASHADE_MEMORY_LIMIT, parses and runs the chosen command; returns the exit code.
int run_command_line(CLI::App& root, int argc, char** argv);

}  // namespace ts::app
