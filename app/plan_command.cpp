// `terrashade plan tiles|relight`: what a job costs before it is run on a cluster (docs/scale.md).
#include "app/command.hpp"

namespace ts::app {

void add_plan_tiles_command(CLI::App& plan);
void add_plan_relight_command(CLI::App& plan);

void add_plan_command(CLI::App& root) {
    CLI::App* plan = root.add_subcommand(
        "plan", "The work of a tiles or relight job: tiles per zoom or frames, the shard count for a wall time from "
                "a measured rate, and the storage (docs/scale.md)");
    plan->require_subcommand(1);
    add_plan_tiles_command(*plan);
    add_plan_relight_command(*plan);
}

}  // namespace ts::app
