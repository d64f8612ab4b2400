#include "app/options/colors_option.hpp"

#include "app/io_plan.hpp"
#include "app/options/within_range.hpp"
#include "core/util/error.hpp"

namespace ts::app {

void add_colors_options(CLI::App& cmd, ColorsArgs& a) {
    cmd.add_option("--colors", a.colors,
                   "Land colours: " + render::palette_names() +
                       " (built in: hypsometric tints fitted to the DEM's height range; grey for pure relief) or a "
                       "colour table FILE in gdaldem color-relief's text format (HEIGHT|N% R G B per line) "
                       "(docs/colors.md)")
        ->capture_default_str();
    cmd.add_option("--snow-line", a.snow_line_m,
                   "Snow and ice above this height in metres (not on cliffs); no snow unless given or in --materials")
        ->check(within(-500, 9000));
}

render::ColorDesign color_design(const ColorsArgs& a) {
    render::ColorDesign d;
    if (auto named = render::Palette::named(a.colors)) {
        d.palette = *named;
    } else {
        if (a.colors.empty()) throw InputError("--colors: give a palette (" + render::palette_names() + ") or a file");
        std::error_code ec;
        if (!std::filesystem::is_regular_file(a.colors, ec))
            throw InputError("--colors " + a.colors + ": neither a built-in palette (" + render::palette_names() +
                             ") nor a colour table file");
        d.palette = render::Palette::read(a.colors);
    }
    d.snow_line_m = a.snow_line_m;
    return d;
}

void plan_colors_input(IoPlan& plan, const ColorsArgs& a) {
    if (!render::Palette::named(a.colors)) plan.input("--colors", a.colors);
}

}  // namespace ts::app
