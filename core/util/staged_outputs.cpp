#include "core/util/staged_outputs.hpp"

#include <system_error>

#include "core/util/error.hpp"
#include "core/util/temp_files.hpp"

namespace ts {
namespace fs = std::filesystem;

StagedOutputs::~StagedOutputs() {
    for (const auto& [tmp, target] : staged_) {
        std::error_code ec;
        fs::remove(tmp, ec);
        temp_files::forget(tmp);
    }
}

void StagedOutputs::stage(const fs::path& target, const std::function<void(const fs::path&)>& write) {
    const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw input_error(target.string(), "output directory does not exist");
    if (fs::is_directory(target, ec)) throw input_error(target.string(), "is a directory, expected an output file name");
    const fs::path tmp = temp_files::sibling_for(target);
    temp_files::track(tmp);
    try {
        write(tmp);
    } catch (const InputError& e) {
        fs::remove(tmp, ec);
        temp_files::forget(tmp);
        // "TMP: problem" names a hidden temporary (or a writer's own temporary beside it), which
        // the user never asked for: the message names the output instead.
        const std::string what = e.what();
        const auto colon = what.find(": ");
        const std::string named = colon == std::string::npos ? "" : fs::path(what.substr(0, colon)).filename().string();
        if (named.starts_with(".") && named.find(".tmp-") != std::string::npos)
            throw input_error(target.string(), what.substr(colon + 2));
        throw;
    } catch (...) {
        fs::remove(tmp, ec);
        temp_files::forget(tmp);
        throw;
    }
    staged_.emplace_back(tmp, target);
}

void StagedOutputs::commit() {
    const auto moves = std::move(staged_);
    staged_.clear();
    temp_files::commit(moves);
}

}  // namespace ts
