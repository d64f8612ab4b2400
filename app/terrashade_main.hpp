#pragma once
// terrashade's whole command line: every command registered on one root, parsed and run. It is
// part of ts_app, so main.cpp stays one call and does not compile CLI11 once more on its own.

namespace ts::app {

// What terrashade's main() returns: `bench ...` forwarded to terrashade-bench, otherwise the
// chosen command's exit code (app/exit_codes.hpp).
int terrashade_main(int argc, char** argv);

}  // namespace ts::app
