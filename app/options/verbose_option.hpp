#pragma once
// -v/--verbose, one flag with one meaning for every command: say what was chosen and why.
#include <CLI/CLI.hpp>

namespace ts::app {

void add_verbose_flag(CLI::App& cmd, bool& verbose);

}  // namespace ts::app
