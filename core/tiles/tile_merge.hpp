#pragma once
// `terrashade merge` of tile shards: the N shards of one tile job (tiles --shard K/N, each
// finished) into one tile set equal to a single-process run: the same tiles with the same bytes,
// the same metadata (the shard's own `terrashade_shard` row is the one left out). Refused
// (ts::InputError, nothing written): a missing or unfinished shard, a shard twice, shards of
// different jobs or metadata, a tile in two shards with different bytes. The output appears
// whole or not at all (built under a temporary name, renamed at the end); an existing MBTiles
// file is replaced in one rename, an existing non-empty folder is refused.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace ts::tiles {

struct MergeStats {
    std::size_t shards = 0;
    std::size_t tiles = 0;       // in the output
    std::size_t duplicates = 0;  // identical tiles met again (shards that overlap): kept once
};

MergeStats merge_mbtiles(const std::vector<std::filesystem::path>& shards, const std::filesystem::path& out);
MergeStats merge_xyz(const std::vector<std::filesystem::path>& shards, const std::filesystem::path& out);

// FNV-1a 64 of a tile's bytes: what duplicates and the tests compare.
std::uint64_t content_hash(const std::uint8_t* data, std::size_t size);

}  // namespace ts::tiles
