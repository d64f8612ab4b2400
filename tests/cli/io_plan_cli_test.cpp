// Every command checks its inputs and outputs before it computes (app/io_plan.hpp), changes no
// output when it fails (core/util/staged_outputs.hpp), and says in one line what it wrote.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/cli/reliability_support.hpp"

namespace ts::cli_test {
namespace {
namespace fs = std::filesystem;


// Hidden files are what write_atomically and StagedOutputs name their temporaries.
int hidden_files(const fs::path& dir) {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir)) n += e.path().filename().string().starts_with(".");
    return n;
}

struct Timed {
    Result result;
    double seconds;
};
Timed timed_run(const std::string& args) {
    const auto t0 = std::chrono::steady_clock::now();
    Result r = run(ts_cmd(args));
    return {r, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
}

void expect_one_line_naming(const Result& r, const std::string& what, const std::string& args) {
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << args << "\n" << r.err;
}

// Each bad path of each command fails at once: on the whole DEM with many directions the work
// would take far longer than the bound (tens of seconds).
TEST(IoPlanCli, EveryCommandChecksItsPathsBeforeTheWork) {
    const fs::path dir = temp_dir("plan_first");
    const std::string missing_dir = (dir / "nope" / "x").string();
    fs::create_directories(dir / "a_directory.png");
    std::ofstream(dir / "x.jpg") << "a file, not a directory";
    const std::string slow_render = "render " + quote(kDem) + " --directions 1024" + kSun;
    const std::string slow_vis = "visibility " + quote(kDem) + " --directions 4096";
    const std::string times = " --times 2025-06-21T06:00:00Z/2025-06-21T08:00:00Z/PT1H";
    const std::pair<std::string, std::string> cases[] = {
        {slow_render + " --out " + quote(missing_dir + ".png"), "does not exist"},
        {slow_render + " --out " + quote((dir / "a_directory.png").string()), "is a directory"},
        {slow_render + " --out " + quote((dir / "x.jpg").string()), "unsupported output format '.jpg'"},
        {slow_render + " --sky hdr:/nonexistent/sky.exr --out " + quote((dir / "x.png").string()), "(--sky)"},
        {slow_render + " --albedo /nonexistent/ortho.tif --out " + quote((dir / "x.png").string()), "(--albedo)"},
        {slow_render + " --out " + quote((dir / "x.png").string()) + " --sun-visibility " +
             quote(missing_dir + ".tif"), "(--sun-visibility)"},
        {slow_render + " --out " + quote((dir / "x.tif").string()) + " --sun-visibility " +
             quote((dir / "." / "x.tif").string()), "written twice"},
        {"relight " + quote(kDem) + " --directions 1024" + times + " --sky /nonexistent/sky.hdr --out " +
             quote((dir / "frames").string()), "(--sky)"},
        {"relight " + quote(kDem) + times + " --out " + quote((dir / "x.jpg" / "f").string()), "not a directory"},
        {"relight " + quote(kDem) + " --times-file /nonexistent/times.txt --out " + quote((dir / "f").string()),
         "(--times-file)"},
        {slow_vis + " --svf " + quote(missing_dir + ".tif"), "(--svf)"},
        {slow_vis + " --svf " + quote((dir / "svf.tif").string()) + " --horizons " + quote(missing_dir + ".tif"),
         "(--horizons)"},
        {slow_vis + " --sky-visible " + quote((dir / "s.jpg").string()), "unsupported output format"},
        {slow_vis + " --horizons " + quote((dir / "h.png").string()), "PNG holds only"},
        {"hillshade " + quote(kDem) + " --out " + quote(missing_dir + ".png"), "does not exist"},
        {"info /nonexistent/dem.tif", "no such file"},
        {"bench render " + quote(kDem) + " --csv " + quote(missing_dir + ".csv"), "(--csv)"},
        {"bench sun " + quote(kDem) + " --csv " + quote(missing_dir + ".csv"), "(--csv)"},
        {"bench visibility " + quote(kDem) + " --csv " + quote(missing_dir + ".csv"), "(--csv)"},
        {"bench sh --csv " + quote(missing_dir + ".csv"), "(--csv)"},
        {"bench relight " + quote(kDem) + " --keep " + quote((dir / "x.jpg" / "k").string()), "(--keep)"},
        {"bench transfer /nonexistent/dem.tif", "no such file"},
        {"bench insolation " + quote(kDem) + " --csv " + quote(missing_dir + ".csv"), "(--csv)"},
        {"bench insolation " + quote(kDem) + " --date 2024-02-30", "--date"},
        {"tiles " + quote(kDem) + " --zoom 8-14 --directions 256 --out " + quote(missing_dir + ".mbtiles"),
         "does not exist (--out)"},
        {"tiles " + quote(kDem) + " --zoom 8-14 --out " + quote((dir / "x.jpg").string()), "is a file"},
        {"tiles /nonexistent/dem.tif --zoom 8 --out " + quote((dir / "tiles").string()), "no such file (DEM)"},
    };
    for (const auto& [args, what] : cases) {
        const Timed t = timed_run(args);
        expect_one_line_naming(t.result, what, args);
        EXPECT_LT(t.seconds, 3.0) << args;
    }
    EXPECT_FALSE(fs::exists(dir / "frames"));
    EXPECT_FALSE(fs::exists(dir / "tiles"));
    EXPECT_EQ(hidden_files(dir), 0);
}

TEST(IoPlanCli, AFailedRenderChangesNoOutput) {
    const fs::path dir = temp_dir("plan_none");
    const fs::path png = dir / "ex.png", sv = dir / "sv.tif";
    std::ofstream(png) << "the previous picture";
    std::ofstream(sv) << "the previous visibility";
    const std::string args = "render " + quote(kDem) + kCrop + kSun + " --out " + quote(png.string()) +
                             " --sun-visibility /nonexistent/sv.tif";
    expect_one_line_naming(run(ts_cmd(args)), "/nonexistent/sv.tif", args);
    EXPECT_EQ(slurp(png), "the previous picture");
    // A camera below the terrain is found after the DEM is read: still nothing changes.
    const std::string below = "render " + quote(kDem) + kCrop + kSun +
                              " --view perspective --camera 5.75,45.2,10,0,-10,60 --out " + quote(png.string()) +
                              " --sun-visibility " + quote(sv.string());
    expect_one_line_naming(run(ts_cmd(below)), "below the terrain", below);
    EXPECT_EQ(slurp(png), "the previous picture");
    EXPECT_EQ(slurp(sv), "the previous visibility");
    EXPECT_EQ(hidden_files(dir), 0);
}

TEST(IoPlanCli, EveryWritingCommandSaysWhatItWrote) {
    const fs::path dir = temp_dir("plan_wrote");
    const std::string dem = quote(kDem) + kCrop;
    const auto p = [&](const char* name) { return (dir / name).string(); };
    const std::pair<std::string, std::string> cases[] = {
        {"hillshade " + dem + " --out " + quote(p("h.png")), "wrote " + p("h.png") + " (101x101)"},
        {"render " + dem + kSun + " --out " + quote(p("r.png")) + " --sun-visibility " + quote(p("sv.tif")),
         "wrote " + p("sv.tif")},
        {"render " + dem + kSun + " --out " + quote(p("r.png")), "wrote " + p("r.png") + " (101x101)"},
        {"visibility " + dem + " --directions 8 --svf " + quote(p("svf.png")) + " --horizons " + quote(p("hz.tif")),
         "wrote " + p("hz.tif") + " (8 bands)"},
        {"relight " + dem + " --times 2025-06-21T08:00:00Z/2025-06-21T09:00:00Z/PT1H --out " + quote(p("frames")),
         "relit 2 frames (101x101) into " + p("frames")},
    };
    for (const auto& [args, line] : cases) {
        const Result r = run(ts_cmd(args));
        ASSERT_EQ(r.exit_code, 0) << args << "\n" << r.err;
        EXPECT_NE(r.out.find(line), std::string::npos) << args << "\n" << r.out;
    }
    EXPECT_EQ(hidden_files(dir), 0);
}

}  // namespace
}  // namespace ts::cli_test
