// The mesh fuzz seeds (tests/fuzz/corpus/mesh_file, mesh_scene) and every input the mesh fuzzers
// once crashed or hung on (tests/fuzz/regressions/mesh_*), through the same feed as the fuzz
// targets: each seed reads, each regression input reads or is one ts::InputError. Runs in the
// ordinary build, so a fixed crash stays fixed without clang or libFuzzer.
#include <filesystem>
#include <vector>

#include <gtest/gtest.h>

#include "tests/fuzz/fuzz_files.hpp"
#include "tests/fuzz/mesh_fuzz_inputs.hpp"

namespace fs = std::filesystem;

namespace {

using ts::fuzz::files_in;
using ts::fuzz::read_all;

// Feeds every file of tests/fuzz/<kind>/<target>/; counts the files and those that read.
void replay(const std::string& kind, const std::string& target, int& files, int& read) {
    const auto feed = ts::fuzz::mesh_feed_for(target);
    ASSERT_NE(feed, nullptr);
    for (const fs::path& p : files_in(fs::path(TS_SOURCE_DIR) / "tests" / "fuzz" / kind / target)) {
        const std::string bytes = read_all(p);
        SCOPED_TRACE(p.string());
        try {
            read += feed(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()) == ts::fuzz::MeshOutcome::read;
        } catch (const std::exception& e) {
            ADD_FAILURE() << p << ": not an InputError: " << e.what();
        }
        ++files;
    }
}

TEST(MeshFuzzInputs, EverySeedIsAMeshThatReads) {
    for (const char* target : {"mesh_file", "mesh_scene"}) {
        int files = 0, read = 0;
        replay("corpus", target, files, read);
        EXPECT_GE(files, 2) << target;
        EXPECT_EQ(read, files) << target;
    }
}

TEST(MeshFuzzInputs, EveryRegressionInputReadsOrIsOneInputError) {
    int files = 0, read = 0;
    for (const char* target : {"mesh_file", "mesh_scene"}) replay("regressions", target, files, read);
    EXPECT_GE(files, 2);  // the PLY inputs assimp loops on, stopped at the feed's timeout
}

}  // namespace
