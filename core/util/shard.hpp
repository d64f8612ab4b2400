#pragma once
// One worker's part of a job split over many processes or machines: shard K of N (0 <= K < N).
// The shard comes from `--shard K/N`, or else from the scheduler's environment, so the same
// command line runs under a Slurm job array or a Kubernetes Indexed Job (docs/scale.md):
//   Slurm: K = (SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN) / SLURM_ARRAY_TASK_STEP,
//          N = SLURM_ARRAY_TASK_COUNT (an array need not start at 0, e.g. --array=1-8);
//   Kubernetes: K = JOB_COMPLETION_INDEX, N = TERRASHADE_SHARD_COUNT (Kubernetes does not pass
//          .spec.completions to the pod: set it in the pod's env to the same number).
// How a job's items are split lies with each job: tiles by quadkey (core/tiles/tile_shard.hpp),
// frames by index (frame_range below).
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ts {

struct Shard {
    int index = 0;  // K
    int count = 1;  // N
    std::string source;  // the environment variable that set it (empty: the command line), for messages
    bool whole() const { return count == 1; }
    friend bool operator==(const Shard& a, const Shard& b) { return a.index == b.index && a.count == b.count; }
};

// The most shards a job is split into (above Slurm's default MaxArraySize of 1001 on purpose:
// a big array may be made of several arrays).
inline constexpr int kMaxShards = 1000000;

// "K/N" with 0 <= K < N <= kMaxShards; ts::QuantityError (Quantity::shard) otherwise, or, when
// the text comes from a file, ts::InputError naming `source` (e.g. "FILE:").
Shard parse_shard(std::string_view text, std::string_view source = {});

// The shard from the environment as described above, nullopt if none is set; ts::InputError
// on a partial or inconsistent set (a task id without a count, an index >= the count).
// `get` reads one variable (nullptr if unset): std::getenv in the commands, a map in tests.
using EnvironmentReader = std::function<const char*(const char*)>;
std::optional<Shard> shard_from_environment(const EnvironmentReader& get);

// --shard if given, else the environment, else the whole job (0/1).
Shard resolve_shard(const std::string& flag_text, const EnvironmentReader& get);

// "K/N" for messages and metadata.
std::string shard_text(const Shard& shard);

// Frames [begin, end) of shard K among `frames` by index: contiguous blocks whose sizes differ
// by at most one, the larger ones first; together the N blocks are 0..frames-1, once each.
struct IndexRange {
    std::size_t begin = 0, end = 0;
    std::size_t size() const { return end - begin; }
};
IndexRange frame_range(std::size_t frames, const Shard& shard);

}  // namespace ts

namespace ts {

// The inputs of a merge are the N shards of one job, each once: ts::InputError naming what is
// wrong otherwise (an input that is no finished shard, shards of different N, a shard given
// twice, the shards missing). `shards[i]` belongs to `names[i]`; nullopt = no shard recorded.
void check_complete_shard_set(const std::vector<std::string>& names, const std::vector<std::optional<Shard>>& shards);

}  // namespace ts
