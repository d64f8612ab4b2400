#include "core/util/temp_files.hpp"

#include <fstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/util/error.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {
using ts::test::fresh_dir;
}  // namespace

TEST(TempFiles, SiblingIsHiddenBesideTheTargetWithItsExtensionAndOurPid) {
    const fs::path t = "/some/dir/frame_0003.png";
    const fs::path a = ts::temp_files::sibling_for(t), b = ts::temp_files::sibling_for(t);
    EXPECT_EQ(a.parent_path(), t.parent_path());
    EXPECT_EQ(a.extension(), ".png");
    EXPECT_EQ(a.filename().string().rfind(".frame_0003.tmp-" + std::to_string(::getpid()) + "-", 0), 0u) << a;
    EXPECT_NE(a, b);
}

TEST(TempFiles, CommitRenamesInOrderAndCounts) {
    const fs::path dir = fresh_dir("commit");
    const std::pair<fs::path, fs::path> moves[] = {{dir / ".a.tmp", dir / "a"}, {dir / ".b.tmp", dir / "b"}};
    for (const auto& m : moves) {
        ts::temp_files::track(m.first);
        std::ofstream(m.first) << "x";
    }
    const auto before = ts::temp_files::committed_count();
    ts::temp_files::commit(moves);
    EXPECT_EQ(ts::temp_files::committed_count(), before + 2);
    EXPECT_TRUE(fs::exists(dir / "a"));
    EXPECT_TRUE(fs::exists(dir / "b"));
    EXPECT_FALSE(fs::exists(dir / ".a.tmp"));
}

TEST(TempFiles, FailedCommitRemovesTheRestAndNamesTheTarget) {
    const fs::path dir = fresh_dir("fail");
    const std::pair<fs::path, fs::path> moves[] = {{dir / ".a.tmp", dir / "gone" / "a"}, {dir / ".b.tmp", dir / "b"}};
    for (const auto& m : moves) {
        ts::temp_files::track(m.first);
        std::ofstream(m.first) << "x";
    }
    try {
        ts::temp_files::commit(moves);
        FAIL() << "a rename into a missing directory must fail";
    } catch (const ts::InputError& e) {
        EXPECT_NE(std::string(e.what()).find((dir / "gone" / "a").string()), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::is_empty(dir));
}
