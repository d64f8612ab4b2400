#pragma once
// --sky, one declaration for every command that lights with a sky (render, relight, tiles, fly).
#include <string>

#include <CLI/CLI.hpp>

namespace ts::app {

void add_sky_option(CLI::App& cmd, std::string& sky);

}  // namespace ts::app
