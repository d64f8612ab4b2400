#pragma once
// --max-error E, the relative radiance error bound of render, relight and tiles (fly takes
// E[,PX] and visibility an svf RMSE, with these checks and lines).
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace ts::app {

void add_max_error_option(CLI::App& cmd, std::optional<double>& max_error);
// E > 0, and no quality flag the bound chooses given as well (`given`: the first of them, or empty).
void check_max_error(const std::optional<double>& max_error, const std::string& given);
// The line printed for a choice: "--max-error E: <core's reason>".
std::string max_error_line(const std::string& reason);

}  // namespace ts::app
