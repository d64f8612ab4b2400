#include "app/options/threads_option.hpp"

#include <string>
#include "app/options/within_range.hpp"

namespace ts::app {

void add_threads_option(CLI::App& cmd, int& threads) {
    cmd.add_option("--threads", threads, "Worker threads, 1.." + std::to_string(kMaxThreads) + " (0 = one per core)")
        ->capture_default_str()
        ->check(within(0, kMaxThreads));
}

}  // namespace ts::app
