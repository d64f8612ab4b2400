// `--shard` of tiles and relight, `plan` and `merge` as a user types them, without a scheduler
// (the Slurm job array itself: tests/scale/slurm_shards_test.sh).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/cli/cli_support.hpp"

namespace {

using ts::cli_test::quote;
using ts::cli_test::Result;
using ts::cli_test::run_ts;

const std::string kQuotedDem = quote(ts::cli_test::kDem);

int count_lines(const std::string& s, const std::string& prefix) {
    int n = 0;
    std::size_t pos = 0;
    while ((pos = s.find("\n" + prefix, pos)) != std::string::npos) ++n, ++pos;
    return n + (s.starts_with(prefix) ? 1 : 0);
}

TEST(ShardCli, MalformedShardIsOneLineExit2BeforeWork) {
    const auto dir = ts::cli_test::temp_dir("bad_shard");
    for (const char* bad : {"3/3", "1", "x/4", "-1/2", "0/0"}) {
        const Result r = run_ts("tiles " + kQuotedDem + " --zoom 0-8 --style hillshade --shard " + bad + " --out " +
                             quote((dir / "t.mbtiles").string()));
        EXPECT_EQ(r.exit_code, 2) << bad;
        EXPECT_EQ(count_lines(r.err, "terrashade:"), 1) << r.err;
        EXPECT_NE(r.err.find("--shard"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "t.mbtiles.partial"));
    }
    const Result r = run_ts("relight " + kQuotedDem + " --times 2025-06-21T06:00Z/2025-06-21T12:00Z/PT3H --exposure 13 --shard 2/2 --out " +
                         quote((dir / "frames").string()));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--shard 2/2"), std::string::npos) << r.err;
    // More insolation shards than the DEM has rows: every shard refuses (a merge could never be
    // whole), the first one too, not only those left without rows.
    const Result many = run_ts("insolation " + kQuotedDem + " --crop 5.7,45.2,5.72,45.22 --from 2025-06-21 --to 2025-06-21 "
                               "--shard 0/5000 --out " + quote((dir / "i.tif").string()));
    EXPECT_EQ(many.exit_code, 2) << many.err;
    EXPECT_NE(many.err.find("use at most"), std::string::npos) << many.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "i.tif"));
}

TEST(ShardCli, EnvironmentGivesTheShard) {
    const auto dir = ts::cli_test::temp_dir("env_shard");
    // --array=1-3: task 2 is shard 1 of 3.
    const Result r = run_ts("tiles " + kQuotedDem + " --zoom 0-9 --style hillshade --out " + quote((dir / "s.mbtiles").string()),
                            "SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=3 ");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("shard 1/3 (from SLURM_ARRAY_TASK_ID)"), std::string::npos) << r.out;
    const Result k = run_ts("tiles " + kQuotedDem + " --zoom 0-9 --style hillshade --out " + quote((dir / "k.mbtiles").string()),
                            "JOB_COMPLETION_INDEX=0 ");
    EXPECT_EQ(k.exit_code, 2);
    EXPECT_NE(k.err.find("TERRASHADE_SHARD_COUNT"), std::string::npos) << k.err;
}

TEST(ShardCli, RelightShardNeedsAFixedExposure) {
    const auto dir = ts::cli_test::temp_dir("relight_auto");
    const Result r = run_ts("relight " + kQuotedDem + " --times 2025-06-21T06:00Z/2025-06-21T12:00Z/PT3H --shard 0/2 --out " +
                         quote((dir / "frames").string()));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--exposure EV"), std::string::npos) << r.err;
}

TEST(ShardCli, MergeReportsMissingShardsAndWritesNothing) {
    const auto dir = ts::cli_test::temp_dir("merge_missing");
    for (int k : {0, 2}) {
        const Result r = run_ts("tiles " + kQuotedDem + " --zoom 0-9 --style hillshade --shard " + std::to_string(k) + "/3 --out " +
                             quote((dir / ("s" + std::to_string(k) + ".mbtiles")).string()));
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    const Result r = run_ts("merge " + quote((dir / "s0.mbtiles").string()) + " " + quote((dir / "s2.mbtiles").string()) +
                         " --out " + quote((dir / "all.mbtiles").string()));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("1 of 3 shards missing (1)"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "all.mbtiles"));
    const Result kinds = run_ts("merge " + quote((dir / "s0.mbtiles").string()) + " --out " + quote((dir / "all").string()));
    EXPECT_EQ(kinds.exit_code, 2);
}

std::string file_bytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(ShardCli, RelightShardsMergeIntoTheSingleRun) {
    const auto dir = ts::cli_test::temp_dir("relight_merge");
    const std::string flags = " --times 2025-06-21T06:00Z/2025-06-21T16:00Z/PT2H --exposure 13 --directions 8 --out ";
    ASSERT_EQ(run_ts("relight " + kQuotedDem + flags + quote((dir / "single").string())).exit_code, 0);
    for (int k : {0, 1, 2})
        ASSERT_EQ(run_ts("relight " + kQuotedDem + flags + quote((dir / ("s" + std::to_string(k))).string()) + " --shard " +
                      std::to_string(k) + "/3")
                      .exit_code,
                  0);
    // Frames 0-1 in shard 0, 2-3 in 1, 4-5 in 2, named as in the whole series.
    EXPECT_TRUE(std::filesystem::exists(dir / "s1" / "frame_0002_2025-06-21T1000Z.png"));
    EXPECT_FALSE(std::filesystem::exists(dir / "s1" / "frame_0000_2025-06-21T0600Z.png"));
    const auto s = [&](int k) { return quote((dir / ("s" + std::to_string(k))).string()); };
    const Result missing = run_ts("merge " + s(0) + " " + s(2) + " --out " + quote((dir / "all").string()));
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_FALSE(std::filesystem::exists(dir / "all"));
    const Result r = run_ts("merge " + s(2) + " " + s(0) + " " + s(1) + " --out " + quote((dir / "all").string()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::size_t files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir / "single")) {
        ++files;
        EXPECT_EQ(file_bytes(e.path()), file_bytes(dir / "all" / e.path().filename())) << e.path().filename();
    }
    EXPECT_EQ(files, 7u);  // 6 frames and times.csv
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir / "all"), {}), 7);
}

TEST(ShardCli, PlanTilesCountsTilesAndShards) {
    const Result r = run_ts("plan tiles " + kQuotedDem + " --zoom 0-12 --style hillshade --wall-time 10s --sample 50");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // 328 tiles (the single run's 327 written + 1 without data, tests/scale), per zoom and in all.
    EXPECT_NE(r.out.find("  all           328"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("shards: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("sbatch --array=0-"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("--time=0:01:00"), std::string::npos) << r.out;  // Slurm's format, whole minutes
    EXPECT_NE(r.out.find("storage: "), std::string::npos) << r.out;
    // A given rate: 328 tiles at 10 tiles/s in 10 s of wall time take 4 shards (no shading measured
    // without a sample).
    const Result g = run_ts("plan tiles " + kQuotedDem + " --zoom 0-12 --style hillshade --wall-time 10s --rate 10 --sample 0");
    ASSERT_EQ(g.exit_code, 0) << g.err;
    EXPECT_NE(g.out.find("shards: 4 for --wall-time 10s"), std::string::npos) << g.out;
    const Result bad = run_ts("plan tiles " + kQuotedDem + " --zoom 0-12 --wall-time soon");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("--wall-time soon"), std::string::npos) << bad.err;
}

TEST(ShardCli, PlanRelightCountsTheFramesRelightRenders) {
    // A June day at Grenoble every 2 hours: 02Z is night (sun -14 degrees), left out as relight
    // leaves it out; with --night include all ten are frames.
    const std::string day = " --times 2025-06-21T02:00:00Z/2025-06-21T20:00:00Z/PT2H --crop 5.65,45.10,5.85,45.30"
                            " --directions 8 --wall-time 1h --rate 10 --setup-seconds 1";
    const Result r = run_ts("plan relight " + kQuotedDem + day);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find(": 9 frames (101x101 texels), 1 night instants left out"), std::string::npos) << r.out;
    const Result all = run_ts("plan relight " + kQuotedDem + day + " --night include");
    ASSERT_EQ(all.exit_code, 0) << all.err;
    EXPECT_NE(all.out.find(": 10 frames (101x101 texels)\n"), std::string::npos) << all.out;
}

}  // namespace
