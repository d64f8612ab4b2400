#include "core/util/atomic_file.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <stdexcept>

#include "core/util/error.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {
using ts::test::fresh_dir;
using ts::test::slurp;
}  // namespace

TEST(AtomicFile, WritesThroughATemporarySibling) {
    const fs::path dir = fresh_dir("ok");
    const fs::path target = dir / "out.txt";
    fs::path seen_tmp;
    ts::write_atomically(target, [&](const fs::path& tmp) {
        seen_tmp = tmp;
        EXPECT_EQ(tmp.parent_path(), target.parent_path());
        EXPECT_EQ(tmp.extension(), ".txt");  // format-by-extension writers still work
        std::ofstream(tmp) << "new";
    });
    EXPECT_EQ(slurp(target), "new");
    EXPECT_FALSE(fs::exists(seen_tmp));
}

TEST(AtomicFile, FailedWriteLeavesTheOldFileWhole) {
    const fs::path dir = fresh_dir("fail");
    const fs::path target = dir / "out.txt";
    std::ofstream(target) << "old";
    EXPECT_THROW(ts::write_atomically(target,
                                      [&](const fs::path& tmp) {
                                          std::ofstream(tmp) << "half";
                                          throw std::runtime_error("disk full");
                                      }),
                 std::runtime_error);
    EXPECT_EQ(slurp(target), "old");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(AtomicFile, MissingDirectoryIsAnInputError) {
    EXPECT_THROW(ts::write_atomically("/nonexistent_dir_ts/x.png", [](const fs::path&) {}), ts::InputError);
}

TEST(AtomicFile, DirectoryTargetIsAnInputError) {
    const fs::path dir = fresh_dir("dir");
    EXPECT_THROW(ts::write_atomically(dir, [](const fs::path&) {}), ts::InputError);
}
