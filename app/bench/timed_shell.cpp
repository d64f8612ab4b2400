#include "app/bench/timed_shell.hpp"

#include <cstdlib>

#include "app/bench/error_stats.hpp"
#include "app/bench/process_usage.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::app {

TimedRun run_timed(const std::string& command) {
    const double cpu0 = cpu_seconds(RUSAGE_CHILDREN);
    const Stopwatch watch;
    TimedRun r;
    r.ok = std::system(command.c_str()) == 0;
    r.wall_s = watch.seconds();
    r.cpu_s = cpu_seconds(RUSAGE_CHILDREN) - cpu0;
    return r;
}

TimedRun median_run(const std::vector<TimedRun>& runs) {
    TimedRun m;
    if (runs.empty()) return m;
    std::vector<double> wall, cpu;
    m.ok = true;
    for (const TimedRun& r : runs) {
        m.ok = m.ok && r.ok;
        wall.push_back(r.wall_s);
        cpu.push_back(r.cpu_s);
    }
    m.wall_s = bench::median(wall);
    m.cpu_s = bench::median(cpu);
    return m;
}

TimedRun run_timed(const std::string& command, int repeats) {
    std::vector<TimedRun> runs;
    for (int i = 0; i < repeats; ++i) {
        runs.push_back(run_timed(command));
        if (!runs.back().ok) break;
    }
    return median_run(runs);
}

}  // namespace ts::app
