#pragma once
// --threads, one declaration for every command that runs workers.
#include <CLI/CLI.hpp>

namespace ts::app {

inline constexpr int kMaxThreads = 256;

// --threads N: 0 = one per core (the default), else 1..kMaxThreads; -1 and the like are refused.
void add_threads_option(CLI::App& cmd, int& threads);

}  // namespace ts::app
