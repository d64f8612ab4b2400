#include "core/util/shard.hpp"

#include <charconv>
#include <cstdint>

#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts {
namespace {

bool parse_int(std::string_view s, std::int64_t& out) {
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return !s.empty() && ec == std::errc() && p == s.data() + s.size();
}

std::int64_t env_int(const EnvironmentReader& get, const char* name) {
    const char* v = get(name);
    std::int64_t out = 0;
    if (!v || !parse_int(v, out)) throw InputError(std::string(name) + "=" + (v ? v : "") + ": not an integer");
    return out;
}

// `source` is the environment variable that gave the shard, or empty for a K/N text `value`.
Shard checked(std::int64_t index, std::int64_t count, std::string source, const std::string& value = {}) {
    auto fail = [&](const std::string& problem) {
        if (source.empty()) throw QuantityError(Quantity::shard, value, problem);
        throw InputError(source + ": " + problem);
    };
    if (count < 1 || count > kMaxShards) fail("the shard count must be 1.." + std::to_string(kMaxShards));
    if (index < 0 || index >= count) fail("shard " + std::to_string(index) + " is not in 0.." + std::to_string(count - 1));
    return {int(index), int(count), std::move(source)};
}

}  // namespace

Shard parse_shard(std::string_view text, std::string_view source) {
    const std::string value(text);
    // From a file (a shard's record): the file names it; from the caller: the quantity does.
    const std::string where = source.empty() ? std::string() : std::string(source) + " " + value;
    const auto slash = text.find('/');
    std::int64_t k = 0, n = 0;
    if (slash == std::string_view::npos || !parse_int(text.substr(0, slash), k) || !parse_int(text.substr(slash + 1), n)) {
        const std::string problem = "give K/N, shard K (from 0) of N (e.g. 0/8)";
        if (where.empty()) throw QuantityError(Quantity::shard, value, problem);
        throw InputError(where + ": " + problem);
    }
    return checked(k, n, where, value);
}

std::optional<Shard> shard_from_environment(const EnvironmentReader& get) {
    if (get("SLURM_ARRAY_TASK_ID")) {
        if (!get("SLURM_ARRAY_TASK_COUNT"))
            throw InputError("SLURM_ARRAY_TASK_ID is set without SLURM_ARRAY_TASK_COUNT: give the shard as K/N");
        const std::int64_t id = env_int(get, "SLURM_ARRAY_TASK_ID");
        const std::int64_t count = env_int(get, "SLURM_ARRAY_TASK_COUNT");
        const std::int64_t min = get("SLURM_ARRAY_TASK_MIN") ? env_int(get, "SLURM_ARRAY_TASK_MIN") : 0;
        const std::int64_t step = get("SLURM_ARRAY_TASK_STEP") ? env_int(get, "SLURM_ARRAY_TASK_STEP") : 1;
        if (step < 1 || (id - min) % step != 0)
            throw InputError("SLURM_ARRAY_TASK_ID " + std::to_string(id) + " is not on the array's step " +
                             std::to_string(step) + " from " + std::to_string(min) + ": give the shard as K/N");
        return checked((id - min) / step, count, "SLURM_ARRAY_TASK_ID");
    }
    if (get("JOB_COMPLETION_INDEX")) {
        if (!get("TERRASHADE_SHARD_COUNT"))
            throw InputError("JOB_COMPLETION_INDEX is set without TERRASHADE_SHARD_COUNT (set it to the Job's "
                             "completions): give the shard as K/N");
        return checked(env_int(get, "JOB_COMPLETION_INDEX"), env_int(get, "TERRASHADE_SHARD_COUNT"),
                       "JOB_COMPLETION_INDEX");
    }
    return std::nullopt;
}

Shard resolve_shard(const std::string& flag_text, const EnvironmentReader& get) {
    if (!flag_text.empty()) return parse_shard(flag_text);
    if (auto s = shard_from_environment(get)) return *s;
    return {0, 1, "none"};
}

std::string shard_text(const Shard& shard) {
    return std::to_string(shard.index) + "/" + std::to_string(shard.count);
}

IndexRange frame_range(std::size_t frames, const Shard& shard) {
    const std::size_t n = std::size_t(shard.count), k = std::size_t(shard.index);
    const std::size_t base = frames / n, extra = frames % n;
    const std::size_t begin = k * base + std::min(k, extra);
    return {begin, begin + base + (k < extra ? 1 : 0)};
}

}  // namespace ts

namespace ts {

void check_complete_shard_set(const std::vector<std::string>& names, const std::vector<std::optional<Shard>>& shards) {
    if (names.empty()) throw InputError("merge: give the shards to merge");
    std::vector<std::string> owner;
    int count = 0;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (!shards[i])
            throw input_error(names[i], "is not a finished shard (a killed shard is finished by running it again, resuming)");
        if (count == 0) count = shards[i]->count, owner.assign(std::size_t(count), "");
        if (shards[i]->count != count)
            throw input_error(names[i], "is shard " + shard_text(*shards[i]) + ", the others are of " +
                                            std::to_string(count));
        std::string& first = owner[std::size_t(shards[i]->index)];
        if (!first.empty())
            throw input_error(names[i], "is shard " + shard_text(*shards[i]) + " again (also " + first + ")");
        first = names[i];
    }
    std::string missing;
    int n_missing = 0;
    for (int k = 0; k < count; ++k)
        if (owner[std::size_t(k)].empty()) {
            if (n_missing < 10) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
            ++n_missing;
        }
    if (n_missing > 0)
        throw InputError("merge: " + std::to_string(n_missing) + " of " + std::to_string(count) +
                         " shards missing (" + missing + (n_missing > 10 ? ", ..." : "") +
                         "): run them (a killed one resumed) and merge again");
}

}  // namespace ts
