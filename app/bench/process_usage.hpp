#pragma once
// What this process (or its finished children) has used so far, from getrusage: the machines
// the benchmarks run on may be shared, so beside wall-clock rates they report CPU time, which
// other processes' load does not inflate, and peak memory.
#include <sys/resource.h>

namespace ts::app {

// CPU seconds (user + system) of this process (RUSAGE_SELF) or of its finished children
// (RUSAGE_CHILDREN).
double cpu_seconds(int who = RUSAGE_SELF);

// Peak resident memory of this process so far, GB.
double peak_rss_gb();

}  // namespace ts::app
