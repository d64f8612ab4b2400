#include "app/bench/timed_shell.hpp"

#include <cstdlib>

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

}  // namespace ts::app
