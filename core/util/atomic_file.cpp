#include "core/util/atomic_file.hpp"

#include "core/util/staged_outputs.hpp"

namespace ts {

void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path&)>& write) {
    // One output staged and committed at once.
    StagedOutputs outputs;
    outputs.stage(target, write);
    outputs.commit();
}

}  // namespace ts
