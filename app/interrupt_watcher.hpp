#pragma once
// Ctrl-C (SIGINT), SIGTERM and SIGHUP (the terminal closed) end a command cleanly: no temporary
// file is left, one line says what was finished (`terrashade: interrupted; 12 of 48 frames
// written`) and what was kept for --resume, and the exit code is 130, 143 or 129 (128 + the
// signal, as shells report it).
//
// Signals belong to the process, not to a command, so this is process-wide state: the one
// exception to "no global state" (with core/util/temp_files.hpp, the list it cleans up).
// main() calls start() before any other thread exists; every thread then inherits a mask that
// blocks both signals, and one watcher thread takes them with sigwait. On a signal it holds the
// temp-file list (no rename can be half-done), stops every other thread where it is (a signal
// of our own whose handler never returns), removes the tracked temporary files, prints the line
// and _exits. Nothing runs in a signal handler but a counter and pause().
#include <cstddef>
#include <cstdint>
#include <string>

namespace ts::app::interrupt {

// Starts the watcher. A signal the process was started with ignored (nohup, `cmd &` in a
// script) stays ignored.
void start();

// From now on an interrupt reports "N of `total` `unit` written" (`unit` a plural noun kept by
// the caller for the process's life, e.g. "frames"), N counting the files committed since
// this call. Without it the line says whether any output was changed.
void report_progress(const char* unit, std::uint64_t total);

// From now on an interrupt adds "; `kept`" to its line: what it leaves on purpose, for --resume
// (e.g. "the tiles so far are kept in t.mbtiles.partial for --resume").
void report_kept(const std::string& kept);

// An index file an interrupt writes once the other threads are stopped (relight's times.csv), so
// that it lists exactly the outputs on disk: `header`, then the line of each ready item whose
// file exists; nothing if none does. Everything is formatted beforehand: the interrupt path
// does not allocate. Lives for the process; forget() once the command wrote the index itself.
class InterruptIndex {
public:
    // Item k: its output file and its line (ending in '\n'), set before the file can appear.
    void set(std::size_t k, const std::string& file, const std::string& line);
    void forget();

private:
    friend InterruptIndex& index_on_interrupt(const std::string&, const std::string&, std::size_t);
    friend void write_index();
    struct Item;
    std::string path_, tmp_, header_;
    Item* items_ = nullptr;
    std::size_t count_ = 0;
};
InterruptIndex& index_on_interrupt(const std::string& path, const std::string& header, std::size_t items);

}  // namespace ts::app::interrupt
