#pragma once
// What `tiles` says about the tile set it made (core/tiles/tile_set_info.hpp): its name and
// description, the data's attribution, its legend; and, for an XYZ folder, the viewer written
// beside the tiles at the end of a run (core/tiles/tile_viewer.hpp).
#include <optional>
#include <string>
#include <vector>

#include "app/quicklook_legend.hpp"
#include "app/tiles_options.hpp"
#include "core/dem/dem.hpp"
#include "core/tiles/tile_export.hpp"
#include "core/tiles/tile_set_info.hpp"

namespace ts::app {

// The legend of a style whose colours stand for values (insolation: the job's ramp, its
// quantity and days; svf: its grey stretch); none for the shaded styles. After
// set_tile_insolation (the default ramp needs the DEM).
std::optional<Legend> tile_set_legend(const TilesArgs& args, const tiles::TileJob& job);

// `name` and `attribution` as given (empty: the defaults, from the DEM files' names: the DEM
// readers find no data source in the files to credit instead).
tiles::TileSetInfo tile_set_info(const std::string& name, const std::string& attribution,
                                 const std::vector<std::string>& dem_files, const dem::Dem& dem,
                                 const tiles::TileJob& job, const std::optional<Legend>& legend);

// tiles.json, index.html and, with a legend, legend.png into `dir`, all three renamed into place
// together (an interrupted run leaves none half-written).
// A lightable set's `lightable` JSON (non-empty) goes beside them as lightable.json.
void write_tile_viewer(const std::string& dir, const tiles::TileSetInfo& info, const std::optional<Legend>& legend,
                       const std::string& lightable = "");

}  // namespace ts::app
