#pragma once
// The temporary files this process has in flight (written, not yet renamed into place), so an
// interrupt can remove them (app/interrupt_watcher.hpp). Signals are per process, so this list
// is process-wide: the one piece of global state in terrashade, kept here so that every writer
// (write_atomically, StagedOutputs) registers the same way.
//
// Protocol: track(tmp) before tmp is created; commit() renames tracked files into place and
// forgets them; forget(tmp) after tmp was removed. An interrupt that holds the list
// (hold_for_exit) sees each file either tracked and not renamed, or renamed and forgotten.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <utility>

namespace ts::temp_files {

// `.<stem>.tmp-<pid>-<random><ext>` beside `target`: hidden, the same extension (writers that
// choose the format by extension still work), pid + random keep concurrent writers apart.
std::filesystem::path sibling_for(const std::filesystem::path& target);

void track(const std::filesystem::path& tmp);
void forget(const std::filesystem::path& tmp);

// A directory of temporary files (bench relight's frames): on an interrupt its files and the
// directory itself are removed. forget_directory() once the command removed it.
void track_directory(const std::filesystem::path& dir);
void forget_directory(const std::filesystem::path& dir);

// An output folder this command created: on an interrupt it is removed if it holds nothing but
// `own_file` (a job description the command wrote first, removed with it; empty: none), so an
// interrupt before the first output leaves no empty folder behind. A folder with outputs stays.
void track_created_directory(const std::filesystem::path& dir, const std::string& own_file = "");

// Renames each (tmp, target) pair in order and forgets the tmps, in one step as an interrupt
// sees it. On a failed rename, the remaining tmps are removed and forgotten too, and
// ts::InputError names the target; renames before it stay done.
void commit(std::span<const std::pair<std::filesystem::path, std::filesystem::path>> moves);

// Files renamed into place by commit() since the process started.
std::uint64_t committed_count();

// For the interrupt watcher only (app/interrupt_watcher.cpp), in this order: hold_for_exit()
// takes the list for good (track, forget and commit block from then on, so no rename is
// half-done and no new file is tracked); once the other threads are stopped,
// remove_held() removes every tracked file and directory and returns how many files existed. Neither allocates.
void hold_for_exit();
std::size_t remove_held();

}  // namespace ts::temp_files
