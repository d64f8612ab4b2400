#pragma once
// One frame series per folder (relight): a folder holds frame_NNNN_<instant>.<ext> files,
// times.csv and, for a shard, the finished-shard marker. A new series goes only into an empty
// or new folder, or replaces the old series when the user says so; a user's other files stay.
#include <filesystem>
#include <string>

namespace ts::render {

// Whether `name` is a file a relight series writes (frame_*.png/.tif/.exr, times.csv, the shard
// marker) or a temporary of one (hidden, ".tmp-" in the name).
bool is_frame_series_file(const std::string& name);

// What claim_frame_folder refuses, refused before any work (nothing changes): a file, or a
// folder that is not empty without `overwrite`. Throws ts::InputError.
void check_frame_folder(const std::filesystem::path& dir, bool overwrite);

// Makes DIR ready for a new series; returns whether it was created. Call it once the series is
// about to be written (its inputs read, its visibility computed): an error or an interrupt
// before then leaves an old series as it was. A folder that is not empty
// is refused (ts::InputError, nothing changed) unless `overwrite`: then the old series' files
// are removed, and only those.
bool claim_frame_folder(const std::filesystem::path& dir, bool overwrite);

}  // namespace ts::render
