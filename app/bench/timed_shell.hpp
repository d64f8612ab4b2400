#pragma once
// One shell command run to its end, timed: wall seconds, and the CPU seconds (user + system) of
// the processes it ran. The benchmarks compare terrashade with other programs on a machine that
// may be shared, where only CPU time is free of the other jobs' load.
#include <string>
#include <vector>

namespace ts::app {

struct TimedRun {
    bool ok = false;  // exit status 0
    double wall_s = 0, cpu_s = 0;
};

// Runs `command` through the shell (std::system) and times it. The CPU time is the growth of
// this process's RUSAGE_CHILDREN: it counts every descendant the command waited for.
TimedRun run_timed(const std::string& command);

// The median of several runs of one thing, wall and CPU each on its own (a shared machine makes
// one run 2x another); not ok if any run failed.
TimedRun median_run(const std::vector<TimedRun>& runs);

// `command` run `repeats` times; their median_run. Stops at the first failure.
TimedRun run_timed(const std::string& command, int repeats);

}  // namespace ts::app
