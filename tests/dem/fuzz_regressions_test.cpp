// Every input the fuzzers crashed on (tests/fuzz/regressions/<reader>/) and every seed
// (tests/fuzz/corpus/<reader>/), through the same feed as the fuzz target: each reads or is
// one ts::InputError, never a crash, a hang or another exception. Runs in the ordinary
// build, so a fixed crash stays fixed without clang or libFuzzer.
#include <filesystem>
#include <iostream>
#include <vector>

#include <gtest/gtest.h>

#include "core/util/memory.hpp"
#include "tests/fuzz/dem_fuzz_inputs.hpp"
#include "tests/fuzz/fuzz_files.hpp"

namespace fs = std::filesystem;

namespace {

const char* const kReaders[] = {"hgt", "hgt_zip", "geotiff"};

using ts::fuzz::files_in;
using ts::fuzz::read_all;

struct FuzzMemoryCap {
    FuzzMemoryCap() { ts::set_memory_cap(ts::fuzz::kMemoryCap); }
    ~FuzzMemoryCap() { ts::set_memory_cap(0); }
};

// Feeds every file of tests/fuzz/<kind>/<reader>/; returns how many there were.
int replay(const std::string& kind, int& read_count) {
    const FuzzMemoryCap cap;  // as in the fuzz targets
    int n = 0;
    for (const char* reader : kReaders) {
        const auto feed = ts::fuzz::feed_for(reader);
        for (const fs::path& p : files_in(fs::path(TS_SOURCE_DIR) / "tests" / "fuzz" / kind / reader)) {
            const std::string bytes = read_all(p);
            SCOPED_TRACE(p.string());
            try {
                read_count += feed(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()) == ts::fuzz::Outcome::read;
            } catch (const std::exception& e) {
                ADD_FAILURE() << p << ": not an InputError: " << e.what();
            }
            ++n;
        }
    }
    return n;
}

}  // namespace

TEST(FuzzRegressions, EveryCrashInputIsAnInputErrorOrReads) {
    int read_count = 0;
    const int n = replay("regressions", read_count);
    std::cout << n << " regression inputs, " << read_count << " read\n";
}

TEST(FuzzRegressions, TheSeedCorpusReads) {
    int read_count = 0;
    const int n = replay("corpus", read_count);
    EXPECT_GE(n, 10);
    // Each reader has seeds that read, so the fuzzers start past the format checks.
    EXPECT_GE(read_count, 8) << "of " << n;
}
