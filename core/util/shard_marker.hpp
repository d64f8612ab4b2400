#pragma once
// Which shard of a tile set or frame series a folder holds, and that it is finished:
// DIR/.terrashade-shard ("K/N" on one line), written once the shard's last tile or frame is in
// place and removed when a run on the folder starts. `terrashade merge` takes a folder only with
// it, so a killed shard is reported rather than merged with holes. (An MBTiles shard says the
// same in its `terrashade_shard` metadata; the file itself only appears when complete.)
#include <filesystem>
#include <optional>

#include "core/util/shard.hpp"

namespace ts {

inline constexpr const char* kShardMarkerFile = ".terrashade-shard";

void write_shard_marker(const std::filesystem::path& dir, const Shard& shard);
void remove_shard_marker(const std::filesystem::path& dir);
// nullopt if DIR has none; ts::InputError if it is malformed.
std::optional<Shard> read_shard_marker(const std::filesystem::path& dir);

}  // namespace ts
