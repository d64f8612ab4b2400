#pragma once
// `terrashade bench ...` stays the user's entry point to the benchmarks, but their code lives in
// a separate executable, terrashade-bench (app/bench/), built with the tests: the product compiles
// no benchmark or study code. terrashade hands such a command line to it unchanged.
#include <CLI/CLI.hpp>

namespace ts::app {

// True when argv names the `bench` command (argv[1] == "bench").
bool is_bench_command(int argc, char** argv);

// Replaces this process with terrashade-bench beside this executable, with argv[2...] as its
// arguments. Returns only when that fails: then one line on stderr says how to build it, and the
// exit code is 2.
int forward_to_bench(int argc, char** argv);

// `bench` in terrashade's --help (the command itself never reaches the parser).
void add_bench_placeholder(CLI::App& root);

}  // namespace ts::app
