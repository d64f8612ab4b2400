#pragma once
// A tile set split into shards by quadkey: every tile at or below the "unit zoom" C belongs to
// the unit of its quadkey's first C digits (its ancestor at zoom C), every tile above C is a unit
// of its own. Units, weighted by their tile count, are dealt to the shards largest first, each to
// the least loaded shard (ties: the smaller quadkey, the lower shard), so a unit's tiles stay on
// one worker (neighbours share DEM reads) and the shards get close to equal work. C is the
// coarsest zoom giving at least kUnitsPerShard units per shard, so no single unit dominates.
//
// The split is a pure function of the plan and N: every shard computes the same assignment, and
// the N shards hold every tile of the plan exactly once (tests/tiles/tile_shard_test.cpp).
#include <cstddef>
#include <vector>

#include "core/tiles/web_mercator.hpp"
#include "core/util/shard.hpp"

namespace ts::tiles {

inline constexpr int kUnitsPerShard = 8;

struct TileShardPlan {
    int unit_zoom = 0;
    std::size_t units = 0;
    // The tile count of each shard (index = shard).
    std::vector<std::size_t> shard_tiles;
};

// How `plan` (tiles in plan order) splits into `count` shards.
TileShardPlan plan_tile_shards(const std::vector<TileId>& plan, int count);

// The tiles of `shard`, in plan order (the whole plan for 0/1).
std::vector<TileId> shard_tiles(const std::vector<TileId>& plan, const Shard& shard);

}  // namespace ts::tiles
