#pragma once
// `--shard K/N` of `tiles` and `relight`, and its fallback to the scheduler's environment
// (core/util/shard.hpp: Slurm job arrays, Kubernetes Indexed Jobs; docs/scale.md).
#include <string>

#include <CLI/CLI.hpp>

#include "core/util/shard.hpp"

namespace ts::app {

void add_shard_option(CLI::App& cmd, std::string& text);
// The shard of this process (ts::InputError on a malformed flag or environment); prints one
// line naming it and where it came from when the job is split.
Shard shard_of_process(const std::string& text);

}  // namespace ts::app
