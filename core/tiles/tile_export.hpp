#pragma once
// A tile set from one DEM: the tiles of zooms z0..z1 that the DEM touches, zoom by zoom. Each
// pixel zoom's ShadeSource is computed once over the whole DEM level it is shaded from (so
// shadows and horizons cross tile borders), only if some tile of that zoom is still to do, and
// kept while later zooms share it; then the tiles are cut in parallel, encoded as PNG and handed
// to the sink. Tiles a resumed sink already has are skipped; tiles that show no data (all
// transparent) are not written.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "core/dem/dem.hpp"
#include "core/tiles/dem_footprint.hpp"
#include "core/tiles/tile_sink.hpp"
#include "core/tiles/lightable_tile.hpp"
#include "core/tiles/tile_style.hpp"
#include "core/util/shard.hpp"

namespace ts {
class ProgressBar;
}

namespace ts::tiles {

struct TileJob {
    int z0 = 0, z1 = 0;
    int tile_size = 256;
    TileShading shading;
    // Tile zoom -> horizon directions for that zoom's source (--max-error: coarse, flattened
    // levels need fewer); zooms not listed use shading.directions.
    std::map<int, int> directions_by_zoom;
    // Each zoom is shaded from the DEM level whose texels match its pixels, moved by this many
    // levels: > 0 coarser (less work, softer), < 0 finer (more work; finer than the pixels it
    // aliases). Clamped to the DEM's levels.
    int level_bias = 0;
    Shard shard;  // this process's part of the tile set (core/tiles/tile_shard.hpp); not in describe_job
    // The DEM the tiles show (its size, footprint and heights: dem_identity), so that tiles of another
    // DEM are another job; in describe_job when set.
    std::string dem;
};

struct TileExportStats {
    std::size_t planned = 0;   // tiles touching the DEM's footprint
    std::size_t resumed = 0;   // already in the sink
    std::size_t written = 0;
    std::size_t empty = 0;     // no data under them: not written
    double source_seconds = 0; // shading the DEM levels
    double tile_seconds = 0;   // cutting, encoding and storing tiles
    // Per DEM level shaded: horizon directions -> blocks shaded with them (--max-error picks a
    // block's from its roughness when the level is shaded in blocks).
    std::map<int, std::map<int, int>> blocks_by_directions;
};

// Checks the job before any work (ts::InputError): zooms in 0..24 with z0 <= z1, a tile size
// of 256 or 512, positive z-factor and exaggeration, directions >= 4.
void check_tile_job(const TileJob& job);

// The tiles to make (of job.shard), in order, and the description of the job that --resume compares.
std::vector<TileId> plan_tiles(const dem::Dem& dem, const TileJob& job);
std::string describe_job(const TileJob& job);
// "WxH west,south,east,north heights HASH": equal for the same DEM (and its shards' runs), different for
// another, also one edited in place.
std::string dem_identity(const dem::Dem& dem);

// How a lightable job's tiles are encoded: its light directions and components, the directions
// the sun can reach at the DEM's centre (where --time places the sun, as for relief).
LightableEncoding lightable_encoding(const dem::Dem& dem, const TileShading& shading);
// The lightable.json of such a job (lightable_sky.hpp).
std::string lightable_json(const dem::Dem& dem, const TileShading& shading);

// The DEM level and vertical scale a pixel zoom is shaded with.
struct ZoomShading {
    int level = 0;
    double vertical_scale = 1;  // z-factor x exaggeration
    // Under --exaggeration auto, the rule's E (zoom_exaggeration.hpp) before legible_relief.hpp
    // raised it; 0 with a constant --exaggeration.
    double rule_exaggeration = 0;
};
ZoomShading zoom_shading(const dem::Dem& dem, const TileJob& job, int pixel_zoom);
// The shading of tile zoom z: job.shading with that zoom's directions.
TileShading shading_of_zoom(const TileJob& job, int z);

// The heights a Horn style shades tile `t` from, with the 1-px halo ((size + 2)^2, row-major),
// and their georef in EPSG:3857: what gdaldem is given to check the tile (tests, --debug-heights).
struct TileHeights {
    std::vector<float> z;
    geo::Georef georef;
};
TileHeights tile_heights(const dem::Dem& dem, const TileJob& job, const TileId& t);

// `progress` (may be null; its total should be plan_tiles().size()) is advanced per tile,
// resumed ones included.
TileExportStats export_tiles(const dem::Dem& dem, const TileJob& job, TileSink& sink, ProgressBar* progress);

}  // namespace ts::tiles
