#pragma once
// What the benchmarks need to run other programs through the shell (the classic pipelines they
// compare with, the bench studies `bench report` gathers).
#include <string>

namespace ts::app {

// s as one shell word: in single quotes, each ' inside written as '\''.
std::string shell_quote(const std::string& s);

// Whether the shell finds `program` on PATH.
bool on_path(const std::string& program);

}  // namespace ts::app
