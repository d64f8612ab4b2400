// One line in the user's words (app/number_flags.hpp, PROJ silenced in core/geo/crs.cpp), and a
// warning or exit 2 where a result would mean nothing (camera, sun, DEM size).
#include <algorithm>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cli_support.hpp"

namespace ts::cli_test {
namespace {
namespace fs = std::filesystem;

TEST(MessagesCli, AWordForANumberSaysNotANumberInEveryCommand) {
    const std::string out = quote((temp_dir("msg_numbers") / "x.png").string());
    const std::string dem = quote(kDem) + kCrop;
    const std::pair<std::string, std::string> cases[] = {
        {"visibility " + dem + " --directions abc --svf " + out, "terrashade: --directions: 'abc' is not a number\n"},
        {"render " + dem + " --directions 2.5" + kSun + " --out " + out,
         "terrashade: --directions: '2.5' is not a whole number\n"},
        {"render " + dem + " --sun-azimuth east --sun-elevation 30 --out " + out,
         "terrashade: --sun-azimuth: 'east' is not a number\n"},
        {"relight " + dem + " --times 2025-06-21T06:00Z/2025-06-21T08:00Z/PT1H --writer-threads many --out " + out,
         "terrashade: --writer-threads: 'many' is not a number\n"},
        {"hillshade " + dem + " --altitude high --out " + out, "terrashade: --altitude: 'high' is not a number\n"},
        {"sun --time 2025-06-21T12:00Z --lat north --lon 5", "terrashade: --lat: 'north' is not a number\n"},
        {"sun --time 2025-06-21T12:00Z --lat nan --lon 5", "terrashade: --lat: 'nan' is not a number\n"},
        {"bench sun " + dem + " --elevations 10 x", "terrashade: --elevations: 'x' is not a number\n"},
        {"bench relight " + dem + " --frames two", "terrashade: --frames: 'two' is not a number\n"},
        {"bench insolation " + quote(kDem) + " --window big", "terrashade: --window: 'big' is not a number\n"},
    };
    for (const auto& [args, line] : cases) {
        const Result r = run(ts_cmd(args));
        EXPECT_EQ(r.exit_code, 2) << args;
        EXPECT_EQ(r.err, line) << args;
    }
    // A number out of range still gives the range.
    const Result range = run(ts_cmd("visibility " + dem + " --directions 0 --svf " + out));
    EXPECT_EQ(range.exit_code, 2);
    EXPECT_NE(range.err.find("must be within 1..4096, got 0"), std::string::npos) << range.err;
    EXPECT_EQ(std::count(range.err.begin(), range.err.end(), '\n'), 1) << range.err;
}

TEST(MessagesCli, AnUnknownCrsIsOneLineOfOurs) {
    const std::string out = quote((temp_dir("msg_crs") / "x.png").string());
    for (const std::string crs : {"EPSG:999999", "+proj=nonsense", "not a crs"}) {
        const Result r = run(ts_cmd("render " + quote(kDem) + kSun + " --extent 0,0,1,1 --extent-crs " + quote(crs) +
                                    " --out " + out));
        EXPECT_EQ(r.exit_code, 2) << crs;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << crs << ": " << r.err;
        EXPECT_TRUE(r.err.starts_with("terrashade: ")) << r.err;
        EXPECT_NE(r.err.find(crs), std::string::npos) << r.err;
    }
}

TEST(MeaninglessResultsCli, ACameraBelowTheTerrainOrSeeingNoneExitsTwoBeforeTheWork) {
    const fs::path dir = temp_dir("warn_camera");
    const std::string base = "render " + quote(kDem) + kCrop + kSun + " --view perspective --size 64x36 --out " +
                             quote((dir / "v.png").string());
    const Result below = run(ts_cmd(base + " --camera 5.75,45.2,10,0,-10,60"));
    EXPECT_EQ(below.exit_code, 2);
    EXPECT_NE(below.err.find("below the terrain"), std::string::npos) << below.err;
    EXPECT_EQ(std::count(below.err.begin(), below.err.end(), '\n'), 1) << below.err;
    // High above the DEM's south-west corner, looking south and up: nothing but sky.
    const Result sky = run(ts_cmd(base + " --camera 5.6,45.0,4000,180,30,40"));
    EXPECT_EQ(sky.exit_code, 2);
    EXPECT_NE(sky.err.find("sees no terrain"), std::string::npos) << sky.err;
    EXPECT_FALSE(fs::exists(dir / "v.png"));
}

TEST(MeaninglessResultsCli, TheSunBelowTheHorizonWarns) {
    const fs::path dir = temp_dir("warn_sun");
    const Result r = run(ts_cmd("render " + quote(kDem) + kCrop + " --sun-azimuth 0 --sun-elevation -10 --out " +
                                quote((dir / "night.png").string())));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("terrashade: warning: the sun is below the horizon"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(MeaninglessResultsCli, ADemTooSmallForAHillshadeExitsTwo) {
    const fs::path dir = temp_dir("warn_small");
    struct Case {
        std::string size, flags, least;
    };
    // With the edges computed (the default) 2x2 has a gradient; with --no-edges a 3x3 window is needed.
    for (const Case& k : {Case{"1 1", "", "at least 2x2"}, Case{"1 10", "", "at least 2x2"},
                          Case{"2 2", " --no-edges", "at least 3x3"}, Case{"2 10", " --no-edges", "at least 3x3"}}) {
        const fs::path small = dir / ("small_" + k.size.substr(0, 1) + "_" + k.size.substr(2) + ".tif");
        const Result made = run("gdal_translate -q -srcwin 100 100 " + k.size + " " + quote(kDem) + " " +
                                quote(small.string()));
        ASSERT_EQ(made.exit_code, 0) << made.err;
        const Result r = run(ts_cmd("hillshade " + quote(small.string()) + k.flags + " --out " +
                                    quote((dir / "h.png").string())));
        EXPECT_EQ(r.exit_code, 2) << k.size;
        EXPECT_NE(r.err.find(k.least), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir / "h.png"));
    }
    // A 2x2 DEM with the edges computed is shaded.
    const fs::path two = dir / "two.tif";
    ASSERT_EQ(run("gdal_translate -q -srcwin 100 100 2 2 " + quote(kDem) + " " + quote(two.string())).exit_code, 0);
    const Result r = run(ts_cmd("hillshade " + quote(two.string()) + " --out " + quote((dir / "two.png").string())));
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(MeaninglessResultsCli, ASingleRowOrColumnDemWarns) {
    const fs::path dir = temp_dir("warn_line");
    const fs::path line = dir / "line.tif";
    ASSERT_EQ(run("gdal_translate -q -srcwin 100 100 5 1 " + quote(kDem) + " " + quote(line.string())).exit_code, 0);
    for (const std::string& args :
         {"visibility " + quote(line.string()) + " --directions 8 --svf " + quote((dir / "svf.tif").string()),
          "render " + quote(line.string()) + kSun + " --directions 8 --out " + quote((dir / "r.png").string())}) {
        const Result r = run(ts_cmd(args));
        EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
        EXPECT_NE(r.err.find("terrashade: warning: " + line.string() + " is 5x1 cells"), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

// Values a command cannot honour are refused in one line before the work, not taken for
// something else: an empty zoom (was zoom 0), a gather that is no divisor of the horizons' (was
// accepted), no shard at a time (was ignored), a DEM given as land cover (its heights taken as
// classes), a 0..360 grid for tiles (its part past 180 dropped).
TEST(MessagesCli, ValuesACommandCannotHonourAreRefusedBeforeTheWork) {
    const fs::path dir = temp_dir("msg_values");
    const std::string dem = quote(kDem) + kCrop;
    ASSERT_EQ(run("gdal_translate -q -a_ullr 175 45.5 185 44.5 " + quote(kDem) + " " + quote((dir / "east.tif").string()))
                  .exit_code,
              0);
    const std::pair<std::string, std::string> cases[] = {
        {"tiles " + dem + " --zoom '' --out " + quote((dir / "t").string()), "--zoom"},
        {"insolation " + dem + " --from 2025-06-21 --to 2025-06-21 --reflection-directions 7 --out " +
             quote((dir / "i.tif").string()),
         "a divisor of --directions"},
        {"plan tiles " + dem + " --zoom 8 --max-parallel 0 --rate 10", "--max-parallel"},
        {"render " + dem + " --materials " + quote(kDem) + kSun + " --out " + quote((dir / "m.png").string()),
         "no ESA WorldCover class"},
        {"tiles " + quote((dir / "east.tif").string()) + " --zoom 4 --out " + quote((dir / "t2").string()), "past 180"},
    };
    for (const auto& [args, words] : cases) {
        const Result r = run(ts_cmd(args));
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
        EXPECT_NE(r.err.find(words), std::string::npos) << args << "\n" << r.err;
    }
    for (const char* out : {"t", "i.tif", "m.png", "t2"}) EXPECT_FALSE(fs::exists(dir / out)) << out;
}

}  // namespace
}  // namespace ts::cli_test

namespace ts::cli_test {
namespace {

// A job that cannot fit is refused before the work, in one line naming what reduces it;
// TERRASHADE_MEMORY_LIMIT stands in for a small machine.
TEST(JobMemoryCli, AJobLargerThanTheMemoryIsRefusedBeforeTheWork) {
    const fs::path dir = temp_dir("job_memory");
    const std::string dem = quote(kSharedDems + "N00E010.hgt");
    const std::string limit = "TERRASHADE_MEMORY_LIMIT=100MB ";
    for (const std::string& args :
         {"visibility " + dem + " --svf " + quote((dir / "svf.tif").string()),
          "render " + dem + " --sun-azimuth 135 --sun-elevation 30 --out " + quote((dir / "r.png").string()),
          "relight " + dem + " --times 2025-06-21T06:00Z/2025-06-21T08:00Z/PT1H --out " + quote((dir / "rl").string())}) {
        const Result r = run(limit + ts_cmd(args));
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
        EXPECT_NE(r.err.find("of memory, 100 MB available (TERRASHADE_MEMORY_LIMIT): use --crop"), std::string::npos)
            << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_FALSE(fs::exists(dir / "svf.tif"));
    EXPECT_FALSE(fs::exists(dir / "r.png"));
    const Result bad = run("TERRASHADE_MEMORY_LIMIT=lots " + ts_cmd("info " + dem));
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("is not a size"), std::string::npos) << bad.err;
    // With room enough the same command runs.
    const Result ok = run("TERRASHADE_MEMORY_LIMIT=2GB " + ts_cmd("visibility " + dem + " --directions 8 --svf " +
                                                              quote((dir / "svf.tif").string())));
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

}  // namespace
}  // namespace ts::cli_test
