#include "app/bench_forward.hpp"

#include "app/exit_codes.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace ts::app {
namespace {
constexpr const char* kBenchExecutable = "terrashade-bench";
}  // namespace

bool is_bench_command(int argc, char** argv) { return argc >= 2 && std::strcmp(argv[1], "bench") == 0; }

int forward_to_bench(int argc, char** argv) {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::filesystem::path bench = ec ? std::filesystem::path(kBenchExecutable)
                                           : self.parent_path() / kBenchExecutable;
    std::vector<char*> args;
    std::string program = bench.string();
    args.push_back(program.data());
    for (int k = 2; k < argc; ++k) args.push_back(argv[k]);
    args.push_back(nullptr);
    execv(program.c_str(), args.data());
    const int err = errno;
    if (err == ENOENT)
        std::fprintf(stderr,
                     "terrashade: bench is a separate executable, not built here (%s): build it with "
                     "`cmake --build --preset release --target terrashade-bench` (scripts/test.sh builds it)\n",
                     program.c_str());
    else
        std::fprintf(stderr, "terrashade: cannot run %s: %s\n", program.c_str(), std::strerror(err));
    return kExitBadInput;
}

void add_bench_placeholder(CLI::App& root) {
    root.add_subcommand("bench",
                        "Measure accuracy and speed (the data behind the charts in docs/); runs terrashade-bench, "
                        "built with the tests");
}

}  // namespace ts::app
