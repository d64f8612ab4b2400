#pragma once
// All outputs of one command, or none: each is written now under a temporary name beside its
// target, and commit() renames them all into place at the end. A command that fails (or is
// interrupted) before commit() leaves every existing output as it was.
//
//   StagedOutputs outputs;
//   outputs.stage(png, [&](const fs::path& tmp) { write_png(tmp, ...); });
//   outputs.stage(tif, [&](const fs::path& tmp) { write_tif(tmp, ...); });
//   outputs.commit();   // both files change here, together
#include <filesystem>
#include <functional>
#include <utility>
#include <vector>

namespace ts {

class StagedOutputs {
public:
    StagedOutputs() = default;
    // Removes the temporary files not committed.
    ~StagedOutputs();
    StagedOutputs(const StagedOutputs&) = delete;
    StagedOutputs& operator=(const StagedOutputs&) = delete;

    // Calls write(tmp) with a temporary sibling of `target` (same extension); `target` is not
    // touched. If write throws, its temporary file is removed and the exception passes on.
    // Throws ts::InputError if `target`'s directory does not exist or `target` is a directory.
    void stage(const std::filesystem::path& target, const std::function<void(const std::filesystem::path& tmp)>& write);

    // Renames every staged file onto its target (as one step for an interrupt) and empties the
    // stage. Throws ts::InputError naming the target whose rename failed.
    void commit();

    std::size_t size() const { return staged_.size(); }

private:
    std::vector<std::pair<std::filesystem::path, std::filesystem::path>> staged_;  // (tmp, target)
};

}  // namespace ts
