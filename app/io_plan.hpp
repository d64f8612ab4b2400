#pragma once
// What one command reads and writes, checked before it computes anything, so a bad path fails
// in a moment instead of after minutes of visibility. Every command (and every new one) lists
// its files here and calls check() before the DEM is read:
//
//   IoPlan plan;
//   plan.inputs("DEM", args.dem.files).input("--sky", sky.hdr_path);
//   plan.output("--out", args.out, {".png", ".tif", ".tiff"});
//   plan.check();
//
// Inputs: exist, are files, are readable. Outputs: the directory exists and is writable, the
// path is not a directory, its extension is one the writer supports, no two outputs are the
// same file. Output directories (relight): exist and are writable, or their parent does.
// No output may be an input, and no output folder (written into, or cleared by --overwrite)
// may hold one: compared as the same file (device and inode, after symlinks and ".."), so
// `hillshade G.tif --out G.tif`, a symlink to G.tif or `dir/../G.tif` are refused before any work.
#include <memory>
#include <string>
#include <vector>

#include "app/output_lock.hpp"

namespace ts::app {

class IoPlan {
public:
    // A file the command reads; `what` names it for the user ("DEM", "--sky", "--times-file").
    // An empty path is skipped (an option not given).
    IoPlan& input(std::string what, std::string path);
    IoPlan& inputs(const std::string& what, const std::vector<std::string>& paths);
    // A folder the command reads (merge's shards): no output may be it or lie inside it.
    IoPlan& input_directory(std::string what, std::string path);
    // A file the command writes, with the extensions its writer supports (lower case, with the
    // dot; matched case-insensitively; none = any). An empty path is skipped.
    IoPlan& output(std::string what, std::string path, std::vector<std::string> extensions);
    // A directory the command writes its files into; it may not exist yet.
    IoPlan& output_directory(std::string what, std::string path);

    // Throws ts::InputError for the first problem: "PATH: problem (WHAT)". Then locks every
    // output and output directory until the plan is destroyed (output_lock.hpp): another
    // terrashade job on one of them is refused here. Keep the plan alive while the command runs.
    void check();

private:
    struct Entry {
        std::string what, path;
        std::vector<std::string> extensions;
    };
    std::vector<Entry> inputs_, input_directories_, outputs_, directories_;
    std::vector<std::unique_ptr<OutputLock>> locks_;
};

}  // namespace ts::app
