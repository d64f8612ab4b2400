#include "core/util/staged_outputs.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/util/error.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {
using ts::test::fresh_dir;
using ts::test::slurp;
std::ptrdiff_t entries(const fs::path& dir) {
    return std::distance(fs::directory_iterator(dir), fs::directory_iterator());
}
}  // namespace

TEST(StagedOutputs, TargetsChangeOnlyAtCommit) {
    const fs::path dir = fresh_dir("commit");
    std::ofstream(dir / "a.txt") << "old a";
    ts::StagedOutputs out;
    out.stage(dir / "a.txt", [](const fs::path& tmp) { std::ofstream(tmp) << "new a"; });
    out.stage(dir / "b.txt", [](const fs::path& tmp) {
        EXPECT_EQ(tmp.extension(), ".txt");
        std::ofstream(tmp) << "new b";
    });
    EXPECT_EQ(slurp(dir / "a.txt"), "old a");
    EXPECT_FALSE(fs::exists(dir / "b.txt"));
    out.commit();
    EXPECT_EQ(slurp(dir / "a.txt"), "new a");
    EXPECT_EQ(slurp(dir / "b.txt"), "new b");
    EXPECT_EQ(entries(dir), 2);
}

TEST(StagedOutputs, UncommittedStageChangesNothingAndLeavesNoTemporary) {
    const fs::path dir = fresh_dir("drop");
    std::ofstream(dir / "a.txt") << "old a";
    {
        ts::StagedOutputs out;
        out.stage(dir / "a.txt", [](const fs::path& tmp) { std::ofstream(tmp) << "new a"; });
        // A later output fails: the command ends without commit().
        EXPECT_THROW(out.stage(dir / "b.txt",
                               [](const fs::path& tmp) {
                                   std::ofstream(tmp) << "half";
                                   throw std::runtime_error("disk full");
                               }),
                     std::runtime_error);
    }
    EXPECT_EQ(slurp(dir / "a.txt"), "old a");
    EXPECT_EQ(entries(dir), 1);
}

TEST(StagedOutputs, MissingDirectoryOrDirectoryTargetIsAnInputError) {
    const fs::path dir = fresh_dir("bad");
    ts::StagedOutputs out;
    EXPECT_THROW(out.stage(dir / "nope" / "x.txt", [](const fs::path&) {}), ts::InputError);
    EXPECT_THROW(out.stage(dir, [](const fs::path&) {}), ts::InputError);
    EXPECT_EQ(out.size(), 0u);
}
