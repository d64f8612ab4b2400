#pragma once
// Existing output is never half-overwritten: writers produce a temporary file beside the
// target and rename it into place only once it is complete.
#include <filesystem>
#include <functional>

namespace ts {

// Calls write(tmp_path) with a temporary path in the target's directory (same extension,
// so format-by-extension writers still work), then renames it onto `target`. If write
// throws, the temporary file is removed and `target` is left untouched.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& tmp)>& write);

}  // namespace ts
