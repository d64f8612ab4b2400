#pragma once
// The legend of a quick-look picture: a title line, the colour ramp as a bar, and the values at
// its ends and middle with their unit. Drawn in a margin under a picture that is not
// georeferenced (insolation quick-looks), or as a side-car NAME_legend.png beside one whose
// pixels must stay the data (the svf quick-look).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/raster/colour_ramp.hpp"

namespace ts::app {

using raster::grey_ramp;
using raster::inferno_ramp;
using raster::Ramp;

struct Legend {
    std::string title;  // what the picture shows, e.g. "sky view factor"
    std::string unit;   // after the upper value; may be empty
    float lo = 0, hi = 1;  // the values at the ramp's ends (the picture clamps beyond them)
    // x in [0, 1] -> sRGB: a quantity's ramp, or a palette's colours over [lo, hi].
    std::function<void(float x, std::uint8_t* rgb)> ramp = grey_ramp;
};

// Rows the strip takes.
int legend_height();
// Draws the strip into rows [y0, y0 + legend_height()) of an RGB image `width` wide.
void draw_legend(std::vector<std::uint8_t>& rgb, int width, int height, int y0, const Legend& legend);
// The strip alone as an RGB PNG `width` wide (at least 200).
void write_legend_png(const std::string& path, int width, const Legend& legend);
// Where a picture's side-car legend goes: DIR/NAME.png -> DIR/NAME_legend.png.
std::string legend_path_for(const std::string& picture);

}  // namespace ts::app
