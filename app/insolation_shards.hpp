#pragma once
// `insolation --shard K/N`: shard K sums the rows [row0, row0 + rows) of the map (contiguous
// blocks, core/util/shard.hpp's frame_range) and writes them as a georeferenced GeoTIFF of its
// own, whose ImageDescription records the job, the shard and its rows; `merge` joins the N of
// them into the map one process would have written (docs/scale.md, docs/insolation.md).
#include <filesystem>
#include <string>
#include <vector>

#include "core/util/shard.hpp"

namespace ts::app {

struct InsolationShardRecord {
    std::string job;  // every option that changes a value, and the DEM (so shards of two jobs never mix)
    Shard shard;
    int row0 = 0, rows = 0, height = 0;  // the shard's rows of the map's `height`
    std::vector<std::string> bands, units;  // the bands' GDAL descriptions and units
};

// The record as the shard's ImageDescription (JSON), and back (nullopt: not a shard's).
std::string insolation_shard_text(const InsolationShardRecord& r);
std::optional<InsolationShardRecord> parse_insolation_shard(const std::string& text);

// Whether a merge input is an insolation shard's GeoTIFF (by its name: .tif or .tiff).
bool is_insolation_shard_path(const std::string& path);

struct InsolationMergeStats {
    std::size_t shards = 0;
    int width = 0, height = 0, bands = 0;
};

// Joins the N shards of one job into `out` (a float Cloud-Optimized GeoTIFF equal to one run's
// --out); ts::InputError naming the file for an input that is not a finished shard, shards of
// two jobs, a shard missing or twice, or rows that do not tile the map.
InsolationMergeStats merge_insolation_shards(const std::vector<std::filesystem::path>& shards,
                                             const std::filesystem::path& out);

}  // namespace ts::app
