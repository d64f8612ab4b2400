#pragma once
// --colors and --snow-line, one declaration for every command that colours land (render,
// relight, tiles --style color, fly): the map's colours by design (core/material/palette.hpp,
// docs/colors.md).
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "core/material/palette_materials.hpp"

namespace ts::app {

class IoPlan;

struct ColorsArgs {
    std::string colors{render::kDefaultPalette};
    std::optional<double> snow_line_m;
};

void add_colors_options(CLI::App& cmd, ColorsArgs& args);

// The palette named, or read from the file given (throws ts::InputError naming --colors), and
// the snow line; percent stops are fitted later to the job's heights.
render::ColorDesign color_design(const ColorsArgs& args);

// A colour-table file among the command's inputs (nothing for a built-in palette's name).
void plan_colors_input(IoPlan& plan, const ColorsArgs& args);

}  // namespace ts::app
