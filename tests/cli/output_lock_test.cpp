// One job per output (app/output_lock.hpp): while a job holds an output, another is refused
// before it touches anything, whatever spelling names the output; nothing is left behind.
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "app/output_lock.hpp"
#include "core/util/error.hpp"
#include "tests/cli/reliability_support.hpp"

namespace ts::cli_test {
namespace {
namespace fs = std::filesystem;

TEST(OutputLock, ASecondHolderIsRefusedWhateverThePathsSpelling) {
    const fs::path dir = temp_dir("output_lock");
    const fs::path out = dir / "tiles";
    const auto lock_files = [] {  // terrashade-UID-HASH.lock in the temporary folder
        std::size_t n = 0;
        std::error_code ec;
        const std::string prefix = "terrashade-" + std::to_string(::getuid()) + "-";
        for (const auto& e : fs::directory_iterator(fs::temp_directory_path(), ec))
            n += e.path().filename().string().starts_with(prefix) && e.path().extension() == ".lock";
        return n;
    };
    const std::size_t before = lock_files();
    {
        app::OutputLock held(out, "--out");
        for (const fs::path& other : {out, fs::path(out.string() + "/"), dir / "." / "tiles", dir / "x" / ".." / "tiles"})
            EXPECT_THROW(app::OutputLock(other, "--out"), InputError) << other;
        try {
            app::OutputLock again(out, "--out");
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("another terrashade job (process " + std::to_string(::getpid()) + ")"), std::string::npos)
                << what;
        }
        app::OutputLock elsewhere(dir / "other", "--out");  // another output is free
    }
    {
        app::OutputLock after(out, "--out");  // let go: free again
        EXPECT_EQ(lock_files(), before + 1);
    }
    EXPECT_EQ(lock_files(), before);  // nothing left behind
}

// A tiles job on a folder another job holds is refused at once and the folder is left as it was.
TEST(OutputLock, ATilesJobOnAHeldFolderIsRefusedBeforeItTouchesIt) {
    const fs::path dir = temp_dir("output_lock_tiles") / "t";
    const std::string cmd = "tiles " + quote(kDem) + kCrop + " --zoom 9 --style hillshade --out " + quote(dir.string());
    ASSERT_EQ(run(ts_cmd(cmd)).exit_code, 0);
    const std::string before = slurp(dir / "tiles.json");
    app::OutputLock held(dir, "--out");
    const Result r = run(ts_cmd(cmd + " --overwrite --sun-azimuth 200"));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("another terrashade job"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(dir / "tiles.json"), before);
}

}  // namespace
}  // namespace ts::cli_test
