#include "core/tiles/tile_shard.hpp"

#include <algorithm>
#include <map>
#include <tuple>

namespace ts::tiles {
namespace {

// A unit: the quadkey prefix as (zoom, x, y) of the unit's root tile.
using UnitKey = std::tuple<int, int, int>;

UnitKey unit_of(const TileId& t, int unit_zoom) {
    if (t.z <= unit_zoom) return {t.z, t.x, t.y};
    const int shift = t.z - unit_zoom;
    return {unit_zoom, t.x >> shift, t.y >> shift};
}

// Quadkey order of two units (a prefix sorts before its extensions).
bool quadkey_less(const UnitKey& a, const UnitKey& b) {
    return quadkey({std::get<0>(a), std::get<1>(a), std::get<2>(a)}) <
           quadkey({std::get<0>(b), std::get<1>(b), std::get<2>(b)});
}

int choose_unit_zoom(const std::vector<TileId>& plan, int count) {
    if (plan.empty()) return 0;
    int z0 = plan.front().z, z1 = plan.front().z;
    for (const TileId& t : plan) z0 = std::min(z0, t.z), z1 = std::max(z1, t.z);
    const std::size_t wanted = std::size_t(count) * kUnitsPerShard;
    for (int c = z0; c < z1; ++c) {
        std::map<UnitKey, int> units;
        for (const TileId& t : plan) units.emplace(unit_of(t, c), 0);
        if (units.size() >= wanted) return c;
    }
    return z1;
}

struct Assignment {
    int unit_zoom = 0;
    std::map<UnitKey, int> shard_of;
    std::vector<std::size_t> load;
};

Assignment assign(const std::vector<TileId>& plan, int count) {
    Assignment a;
    a.unit_zoom = choose_unit_zoom(plan, count);
    std::map<UnitKey, std::size_t> weight;
    for (const TileId& t : plan) ++weight[unit_of(t, a.unit_zoom)];
    std::vector<std::pair<UnitKey, std::size_t>> units(weight.begin(), weight.end());
    std::sort(units.begin(), units.end(), [](const auto& p, const auto& q) {
        if (p.second != q.second) return p.second > q.second;
        return quadkey_less(p.first, q.first);
    });
    a.load.assign(std::size_t(count), 0);
    for (const auto& [key, w] : units) {
        const auto least = std::min_element(a.load.begin(), a.load.end());  // the first of equals
        *least += w;
        a.shard_of[key] = int(least - a.load.begin());
    }
    return a;
}

}  // namespace

TileShardPlan plan_tile_shards(const std::vector<TileId>& plan, int count) {
    const Assignment a = assign(plan, count);
    return {a.unit_zoom, a.shard_of.size(), a.load};
}

std::vector<TileId> shard_tiles(const std::vector<TileId>& plan, const Shard& shard) {
    if (shard.whole()) return plan;
    const Assignment a = assign(plan, shard.count);
    std::vector<TileId> mine;
    for (const TileId& t : plan)
        if (a.shard_of.at(unit_of(t, a.unit_zoom)) == shard.index) mine.push_back(t);
    return mine;
}

}  // namespace ts::tiles
