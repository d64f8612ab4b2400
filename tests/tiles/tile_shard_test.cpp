#include "core/tiles/tile_shard.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <tuple>

#include "core/tiles/dem_footprint.hpp"
#include "core/tiles/tile_count.hpp"

namespace {

using ts::tiles::TileId;

std::tuple<int, int, int> key(const TileId& t) { return {t.z, t.x, t.y}; }

// The Alps at zooms 4-11 (a few thousand tiles) and a small box at 0-6.
std::vector<TileId> alps() { return ts::tiles::tiles_covering({5.5, 44.0, 11.0, 47.5}, 4, 11); }
std::vector<TileId> small() { return ts::tiles::tiles_covering({5.7, 45.1, 5.8, 45.2}, 0, 6); }

TEST(TileShard, ShardsPartitionThePlan) {
    for (const auto& plan : {alps(), small()})
        for (int n : {1, 2, 3, 5, 16, 64}) {
            std::map<std::tuple<int, int, int>, int> owner;
            std::size_t total = 0;
            for (int k = 0; k < n; ++k) {
                const auto mine = ts::tiles::shard_tiles(plan, {k, n});
                total += mine.size();
                for (const TileId& t : mine) {
                    const auto [it, fresh] = owner.emplace(key(t), k);
                    EXPECT_TRUE(fresh) << "tile " << t.z << "/" << t.x << "/" << t.y << " in shards " << it->second
                                       << " and " << k << " of " << n;
                }
            }
            EXPECT_EQ(total, plan.size()) << n << " shards";
            EXPECT_EQ(owner.size(), plan.size()) << n << " shards";
        }
}

TEST(TileShard, KeepsPlanOrderAndIsDeterministic) {
    const auto plan = alps();
    const auto a = ts::tiles::shard_tiles(plan, {2, 5});
    const auto b = ts::tiles::shard_tiles(plan, {2, 5});
    EXPECT_EQ(a, b);
    std::map<std::tuple<int, int, int>, std::size_t> position;
    for (std::size_t i = 0; i < plan.size(); ++i) position[key(plan[i])] = i;
    for (std::size_t i = 1; i < a.size(); ++i) EXPECT_LT(position[key(a[i - 1])], position[key(a[i])]);
}

TEST(TileShard, TilesOfAUnitStayTogether) {
    const auto plan = alps();
    const ts::tiles::TileShardPlan layout = ts::tiles::plan_tile_shards(plan, 4);
    EXPECT_GE(layout.units, 4u * ts::tiles::kUnitsPerShard);
    // Every descendant of a unit-zoom tile is in the same shard as that tile.
    std::map<std::tuple<int, int, int>, int> shard_of_unit;
    for (int k = 0; k < 4; ++k)
        for (const TileId& t : ts::tiles::shard_tiles(plan, {k, 4})) {
            if (t.z < layout.unit_zoom) continue;
            const int s = t.z - layout.unit_zoom;
            const auto [it, fresh] = shard_of_unit.emplace(std::make_tuple(layout.unit_zoom, t.x >> s, t.y >> s), k);
            EXPECT_EQ(it->second, k);
        }
}

TEST(TileShard, LoadIsBalanced) {
    const auto plan = alps();
    for (int n : {2, 3, 8}) {
        const ts::tiles::TileShardPlan layout = ts::tiles::plan_tile_shards(plan, n);
        std::size_t lo = plan.size(), hi = 0, sum = 0;
        for (std::size_t c : layout.shard_tiles) lo = std::min(lo, c), hi = std::max(hi, c), sum += c;
        EXPECT_EQ(sum, plan.size());
        // Within 15% of the mean: the largest unit is at most 1/kUnitsPerShard of a shard's share.
        const double mean = double(plan.size()) / n;
        EXPECT_LE(hi, 1.15 * mean) << n << " shards";
        EXPECT_GE(lo, 0.85 * mean) << n << " shards";
        for (int k = 0; k < n; ++k) EXPECT_EQ(ts::tiles::shard_tiles(plan, {k, n}).size(), layout.shard_tiles[std::size_t(k)]);
    }
}

TEST(TileShard, MoreShardsThanTilesLeavesSomeEmpty) {
    const auto plan = ts::tiles::tiles_covering({5.7, 45.1, 5.8, 45.2}, 3, 3);  // one tile
    ASSERT_EQ(plan.size(), 1u);
    std::size_t total = 0;
    for (int k = 0; k < 3; ++k) total += ts::tiles::shard_tiles(plan, {k, 3}).size();
    EXPECT_EQ(total, 1u);
}

}  // namespace

namespace {

TEST(TileCount, EqualsTheListedTiles) {
    for (const ts::tiles::LonLatBox& box : {ts::tiles::LonLatBox{5.5, 44.0, 11.0, 47.5},
                                            ts::tiles::LonLatBox{-180, -85.0511287798, 180, 85.0511287798},
                                            ts::tiles::LonLatBox{40.0, 39.0, 41.0, 40.0}})
        for (int z = 0; z <= 9; ++z)
            EXPECT_EQ(ts::tiles::count_tiles_covering(box, z), std::int64_t(ts::tiles::tiles_covering(box, z, z).size()))
                << "zoom " << z;
}

}  // namespace
