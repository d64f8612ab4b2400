#include "app/shard_option.hpp"

#include <cstdio>
#include <cstdlib>

namespace ts::app {

void add_shard_option(CLI::App& cmd, std::string& text) {
    cmd.add_option("--shard", text,
                   "Do only shard K of N (from 0) of the work, for a job array (docs/scale.md); default: "
                   "SLURM_ARRAY_TASK_ID/COUNT or JOB_COMPLETION_INDEX/TERRASHADE_SHARD_COUNT if set, else all");
}

Shard shard_of_process(const std::string& text) {
    const Shard s = resolve_shard(text, [](const char* name) { return std::getenv(name); });
    if (!s.whole()) std::printf("shard %s (from %s)\n", shard_text(s).c_str(), s.source.empty() ? "--shard" : s.source.c_str());
    return s;
}

}  // namespace ts::app
