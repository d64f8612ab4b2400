#pragma once
// -v/--verbose, one flag with one meaning for every command: say what was chosen and why.
#include <string>

#include <CLI/CLI.hpp>

namespace ts::app {

// `what`: what this command tells, e.g. "the device and where each stage ran".
void add_verbose_flag(CLI::App& cmd, bool& verbose, const std::string& what);

}  // namespace ts::app
