#pragma once
// The materials of a map by design (docs/colors.md): land takes its colour from a palette of
// height stops, water is decided from data (a void, a flat texel at or below sea level, or
// WorldCover's class 80), snow only above a snow line the user gives, land cover only from a
// raster the user gives. Nothing is guessed from slope.
#include <cstdint>
#include <optional>
#include <vector>

#include "core/dem/dem.hpp"
#include "core/material/material.hpp"
#include "core/material/palette.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/terrain/terrain_normals.hpp"

namespace ts::render {

// A DEM reaching below this holds the sea floor (ETOPO, GEBCO): no dry land lies so deep (the
// Dead Sea's shore, the lowest, is at -430 m).
inline constexpr double kSeaFloorBelowM = -1000.0;

struct ColorDesign {
    Palette palette = *Palette::named(kDefaultPalette);  // percent stops fitted by fit_colors
    // Snow and ice on every texel above this height (metres, +-75 m blend) that is not a cliff
    // too steep to hold it (MaterialRule::snow_max_slope_deg); none if empty.
    std::optional<double> snow_line_m;
    // Set by fit_colors: the DEM's heights are known (a second fit keeps the first).
    bool fitted = false;
    // The DEM holds the sea floor (its lowest height below kSeaFloorBelowM): it has no sea
    // surface, so the flat-sea water rule is off (a sloping sea floor would be land, a flat abyssal
    // plain a mirror) and the sea floor is coloured and shaded as terrain; the default palette
    // adds its bathymetric tints below 0 m (Palette::with_sea_tints).
    bool sea_floor = false;
};

// `design` with its percent stops placed on [lowest, highest]; on a DEM with a sea floor the
// default palette's land tints go on [0, highest] and its sea tints on [lowest, 0).
ColorDesign fit_colors(const ColorDesign& design, double lowest_m, double highest_m);
// ... on the DEM's measured heights (voids excluded), as gdaldem color-relief places N%; a design
// fitted already is returned as it is.
ColorDesign fit_colors(const ColorDesign& design, const dem::Dem& dem);

// Materials per texel. `design.palette` must be fitted (no percent stops left). With a land-cover
// raster (WorldCover codes on the grid, 0 = none), its classes replace the palette where known.
MaterialRaster palette_materials(const terrain::HeightGrid& grid, const NormalField& normals, const ColorDesign& design,
                                 const std::vector<std::uint8_t>& worldcover = {}, const MaterialRule& water = {});

}  // namespace ts::render
