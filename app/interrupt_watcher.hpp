#pragma once
// Ctrl-C (SIGINT) and SIGTERM end a command cleanly: no temporary file is left, one line says
// what was finished (`terrashade: interrupted; 12 of 48 frames written`), and the exit code is
// 130 or 143 (128 + the signal, as shells report it).
//
// Signals belong to the process, not to a command, so this is process-wide state: the one
// exception to "no global state" (with core/util/temp_files.hpp, the list it cleans up).
// main() calls start() before any other thread exists; every thread then inherits a mask that
// blocks both signals, and one watcher thread takes them with sigwait. On a signal it holds the
// temp-file list (no rename can be half-done), stops every other thread where it is (a signal
// of our own whose handler never returns), removes the tracked temporary files, prints the line
// and _exits. Nothing runs in a signal handler but a counter and pause().
#include <cstdint>

namespace ts::app::interrupt {

// Starts the watcher. A signal the process was started with ignored (nohup, `cmd &` in a
// script) stays ignored.
void start();

// From now on an interrupt reports "N of `total` `unit` written" (`unit` a plural noun kept by
// the caller for the process's life, e.g. "frames"), N counting the files committed since
// this call. Without it the line says whether any output was changed.
void report_progress(const char* unit, std::uint64_t total);

}  // namespace ts::app::interrupt
