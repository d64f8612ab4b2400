#pragma once
// `terrashade merge` of relight shards: the N folders of `relight --shard K/N` (each with its
// frames, times.csv and the finished-shard marker) into one folder equal to a single run: every
// frame file once, times.csv with every row in frame order. Refused (ts::InputError, nothing
// written): a missing or unfinished shard, a shard twice, different times.csv headers (frame
// formats), a frame number in two shards with different rows or bytes, a gap in the frame
// numbers. The folder is built under a temporary name and renamed into place.
#include <cstddef>
#include <filesystem>
#include <vector>

namespace ts::render {

struct FrameMergeStats {
    std::size_t shards = 0;
    std::size_t frames = 0;
};

FrameMergeStats merge_frame_series(const std::vector<std::filesystem::path>& shards, const std::filesystem::path& out);

}  // namespace ts::render
