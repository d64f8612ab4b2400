#pragma once
// Each subcommand lives in its own file and registers itself on the root CLI11 app.
// A command reports bad usage or input by throwing ts::InputError (exit 2, one line on
// stderr); it returns normally on success (exit 0).
#include <CLI/CLI.hpp>

namespace ts::app {

void add_info_command(CLI::App& root);
void add_hillshade_command(CLI::App& root);

}  // namespace ts::app
