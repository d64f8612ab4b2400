// A user's data is never written over (app/io_plan.hpp, docs/user-guide.md "Outputs"): no output
// is or holds an input, whatever path names it; one job per output (tiles folders and MBTiles
// files, relight folders), replaced only with --overwrite and then only the old job's files;
// --resume keeps only tiles of the job it continues.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/cli/reliability_support.hpp"

namespace ts::cli_test {
namespace {
namespace fs = std::filesystem;


// Every file under `dir` (relative path -> bytes), symlinks as their target's name.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        const std::string rel = fs::relative(e.path(), dir).string();
        if (e.is_symlink()) files[rel] = "-> " + fs::read_symlink(e.path()).string();
        else if (e.is_regular_file()) files[rel] = slurp(e.path());
        else files[rel] = "<dir>";
    }
    return files;
}

void expect_refused(const Result& r, const std::string& names, const std::string& args) {
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(names), std::string::npos) << args << "\n" << r.err;
}

// Every command that writes, with every way of naming an input as an output: the same path, a
// symlink to it, `dir/../name`, a hard link, an output folder holding it. Each is refused at
// once (exit 2, one line naming the input) and nothing in the folder changes.
TEST(NoOutputOverInputCli, EveryCommandRefusesToWriteOverWhatItReads) {
    const fs::path dir = temp_dir("over_input");
    const auto p = [&](const std::string& name) { return quote((dir / name).string()); };
    fs::copy_file(kDem, dir / "G.tif");
    fs::copy_file(kDem, dir / "A.tif");
    fs::copy_file(kDem, dir / "D.mbtiles");
    fs::create_symlink("G.tif", dir / "link.tif");
    fs::create_symlink("G.tif", dir / "link.mbtiles");
    fs::create_hard_link(dir / "G.tif", dir / "hard.png");
    fs::create_directories(dir / "sub");
    std::ofstream(dir / "sky.hdr") << "#?RADIANCE\n";
    fs::create_symlink("sky.hdr", dir / "sky.png");
    std::ofstream(dir / "materials.json") << "{}\n";
    fs::create_symlink("materials.json", dir / "materials.png");
    std::ofstream(dir / "m.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    fs::create_symlink("m.obj", dir / "m.json");
    fs::create_symlink("m.obj", dir / "m.png");
    std::ofstream(dir / "times.txt") << "2025-06-21T12:00:00Z\n";
    std::ofstream(dir / "path.csv") << "t_s,lon,lat,height_m,heading_deg,pitch_deg,roll_deg\n";
    fs::create_directories(dir / "shard_a" / "8");
    fs::create_directories(dir / "shard_b" / "8");
    const std::map<std::string, std::string> before = snapshot(dir);

    const std::string G = p("G.tif"), render = "render " + G + kSun, dem_dir = quote(dir.string());
    const std::string times = " --times 2025-06-21T06:00:00Z/2025-06-21T08:00:00Z/PT1H";
    const std::pair<std::string, std::string> cases[] = {
        {"hillshade " + G + " --out " + G, "G.tif"},
        {"hillshade " + G + " --out " + p("link.tif"), "G.tif"},
        {"hillshade " + G + " --out " + p("sub/../G.tif"), "G.tif"},
        {"hillshade " + p("link.tif") + " --out " + G, "link.tif"},
        {"hillshade " + G + " --out " + p("hard.png"), "G.tif"},
        {render + " --out " + G, "G.tif"},
        {render + " --out " + p("sub/../link.tif"), "G.tif"},
        {render + " --out x.png --sun-visibility " + p("sub/../G.tif"), "G.tif"},
        {render + " --albedo " + p("A.tif") + " --out " + p("A.tif"), "(--out and --albedo)"},
        {render + " --sky " + p("sky.hdr") + " --out " + p("sky.png"), "(--out and --sky)"},
        {render + " --materials " + p("materials.json") + " --out " + p("materials.png"), "(--out and --materials)"},
        {render + " --mesh " + p("m.obj") + " --at 5.75,45.2,100 --out " + p("m.png"), "(--out and --mesh)"},
        {"visibility " + G + " --svf " + G, "G.tif"},
        {"insolation " + G + " --year 2025 --out " + p("sub/../link.tif"), "G.tif"},
        {"visibility " + G + " --svf " + p("sv.tif") + " --sh " + p("link.tif"), "(--sh and DEM)"},
        {"relight " + G + times + " --out " + dem_dir, "G.tif"},
        {"relight " + quote(kDem) + " --times-file " + p("times.txt") + " --out " + dem_dir, "(--out and --times-file)"},
        {"tiles " + G + " --zoom 8 --out " + dem_dir, "G.tif"},
        {"tiles " + G + " --zoom 8 --out " + p("sub/.."), "G.tif"},
        {"tiles " + p("D.mbtiles") + " --zoom 8 --out " + p("D.mbtiles"), "D.mbtiles"},
        {"tiles " + G + " --zoom 8 --out " + p("link.mbtiles"), "G.tif"},
        {"spheres " + p("m.obj") + " --out " + p("m.json"), "(--out and mesh)"},
        {"merge " + p("shard_a") + " " + p("shard_b") + " --out " + p("shard_a"), "shard_a"},
        {"merge " + p("shard_a") + " " + p("shard_b") + " --out " + p("shard_b/merged"), "shard_b"},
        {"fly " + G + " --frames 1 --path " + p("path.csv") + " --out " + dem_dir, "G.tif"},
        {"fly " + quote(kDem) + " --frames 1 --path " + p("path.csv") + " --out " + dem_dir, "(--out and --path)"},
    };
    const std::pair<std::string, std::string> bench_cases[] = {
        {"bench relight " + G + " --frames 1 --keep " + dem_dir, "G.tif"},
        {"bench tiles " + G + " --reference 5.7,45.2 --reference-out " + dem_dir, "G.tif"},
    };
    std::vector<std::pair<std::string, std::string>> all(std::begin(cases), std::end(cases));
    if (run(ts_cmd("bench --help")).exit_code == 0) all.insert(all.end(), std::begin(bench_cases), std::end(bench_cases));
    for (const auto& [args, names] : all) {
        const Result r = run(ts_cmd(args));
        expect_refused(r, names, args);
        EXPECT_NE(r.err.find("the input "), std::string::npos) << args << "\n" << r.err;
    }
    EXPECT_EQ(snapshot(dir), before) << "a refused command changed the folder";
}

std::set<std::string> tiles_in(const fs::path& dir) {
    std::set<std::string> tiles;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.path().extension() == ".png") tiles.insert(fs::relative(e.path(), dir).string());
    return tiles;
}

std::string tiles_args(const std::string& style, const fs::path& out) {
    return "tiles " + quote(kDem) + kCrop + " --zoom 8-10 --style " + style + " --directions 8 --out " +
           quote(out.string());
}

// The report's case: hillshade tiles in a folder, then a relief job into it. It is refused (with
// and without --resume) and changes nothing; --overwrite replaces the hillshade tiles and only
// them; the folder then equals a fresh relief run, tile for tile.
TEST(OneJobPerOutputCli, TilesFolderHoldsOneJob) {
    const fs::path root = temp_dir("one_job_xyz");
    const fs::path t = root / "t", fresh = root / "fresh";
    ASSERT_EQ(run(ts_cmd(tiles_args("relief", fresh))).exit_code, 0);
    const Result h = run(ts_cmd(tiles_args("hillshade", t)));
    ASSERT_EQ(h.exit_code, 0) << h.err;
    std::ofstream(t / "notes.txt") << "the user's own file";
    const std::map<std::string, std::string> hillshade = snapshot(t);

    expect_refused(run(ts_cmd(tiles_args("relief", t))), "--overwrite", "relief into hillshade");
    expect_refused(run(ts_cmd(tiles_args("relief", t) + " --resume")), "another job", "relief --resume");
    expect_refused(run(ts_cmd(tiles_args("relief", t) + " --resume --overwrite")), "give one", "both flags");
    EXPECT_EQ(snapshot(t), hillshade);

    // The same job continues: every tile is kept.
    const Result again = run(ts_cmd(tiles_args("hillshade", t) + " --resume"));
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_NE(again.out.find("0 written, " + std::to_string(tiles_in(t).size()) + " resumed"), std::string::npos)
        << again.out;

    const Result o = run(ts_cmd(tiles_args("relief", t) + " --overwrite"));
    ASSERT_EQ(o.exit_code, 0) << o.err;
    EXPECT_NE(o.out.find(" 0 resumed"), std::string::npos) << o.out;
    EXPECT_EQ(slurp(t / "notes.txt"), "the user's own file");
    std::map<std::string, std::string> replaced = snapshot(t), expected = snapshot(fresh);
    replaced.erase("notes.txt");
    EXPECT_EQ(replaced, expected) << "the folder is not the relief job's alone";

    // A folder holding something else and no job: refused; --overwrite keeps what is not a tile.
    const fs::path mine = root / "mine";
    fs::create_directories(mine / "photos");
    std::ofstream(mine / "photos" / "cat.png") << "not a tile";
    expect_refused(run(ts_cmd(tiles_args("relief", mine))), "holds no terrashade tile job", "foreign folder");
    ASSERT_EQ(run(ts_cmd(tiles_args("relief", mine) + " --overwrite")).exit_code, 0);
    EXPECT_EQ(slurp(mine / "photos" / "cat.png"), "not a tile");
}

TEST(OneJobPerOutputCli, MbtilesFileHoldsOneJob) {
    const fs::path root = temp_dir("one_job_mbtiles");
    const fs::path t = root / "t.mbtiles";
    ASSERT_EQ(run(ts_cmd(tiles_args("hillshade", t))).exit_code, 0);
    const std::string hillshade = slurp(t);
    expect_refused(run(ts_cmd(tiles_args("relief", t))), "--overwrite", "relief into hillshade");
    expect_refused(run(ts_cmd(tiles_args("relief", t) + " --resume")), "another job", "relief --resume");
    EXPECT_EQ(slurp(t), hillshade);
    EXPECT_FALSE(fs::exists(root / "t.mbtiles.partial"));
    // Not an MBTiles file of ours at all: refused too.
    std::ofstream(root / "other.mbtiles") << "someone else's data";
    expect_refused(run(ts_cmd(tiles_args("relief", root / "other.mbtiles"))), "holds no terrashade tile job",
                   "foreign file");
    EXPECT_EQ(slurp(root / "other.mbtiles"), "someone else's data");

    ASSERT_EQ(run(ts_cmd(tiles_args("hillshade", t) + " --resume")).exit_code, 0);
    const Result o = run(ts_cmd(tiles_args("relief", t) + " --overwrite"));
    ASSERT_EQ(o.exit_code, 0) << o.err;
    EXPECT_NE(slurp(t), hillshade);
    expect_refused(run(ts_cmd(tiles_args("hillshade", t))), "--overwrite", "hillshade into relief");
}

std::vector<std::string> frames_in(const fs::path& dir) {
    std::vector<std::string> frames;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().starts_with("frame_")) frames.push_back(e.path().filename().string());
    std::sort(frames.begin(), frames.end());
    return frames;
}

// A second series into a relight folder gave two frame_0000_* files and a stale times.csv: it is
// refused, and --overwrite replaces the old series' frames and times.csv (and nothing else).
TEST(OneJobPerOutputCli, RelightFolderHoldsOneSeries) {
    const fs::path dir = temp_dir("one_series");
    const std::string base = "relight " + quote(kDem) + kCrop + " --directions 8 --exposure 13 --out " +
                             quote(dir.string());
    ASSERT_EQ(run(ts_cmd(base + " --times 2025-06-21T08:00Z/2025-06-21T10:00Z/PT1H")).exit_code, 0);
    std::ofstream(dir / "notes.txt") << "mine";
    const std::map<std::string, std::string> first = snapshot(dir);
    const std::string second = base + " --times 2025-06-21T14:00Z/2025-06-21T15:00Z/PT1H";
    expect_refused(run(ts_cmd(second)), "--overwrite", second);
    EXPECT_EQ(snapshot(dir), first);
    const Result o = run(ts_cmd(second + " --overwrite"));
    ASSERT_EQ(o.exit_code, 0) << o.err;
    const std::vector<std::string> frames = frames_in(dir);
    ASSERT_EQ(frames.size(), 2u);
    EXPECT_TRUE(frames[0].starts_with("frame_0000_2025-06-21T1400Z")) << frames[0];
    EXPECT_EQ(csv_files(dir / "times.csv"), frames);
    EXPECT_EQ(slurp(dir / "notes.txt"), "mine");
}


// --overwrite replaces the old series only once the new one is about to be written: a new job
// refused for its camera, or one with only night instants, leaves the old frames as they were.
TEST(OneJobPerOutputCli, AFailedOverwriteLeavesTheOldSeries) {
    const fs::path dir = temp_dir("failed_overwrite");
    const std::string base = "relight " + quote(kDem) + kCrop + " --directions 8 --exposure 13 --out " +
                             quote(dir.string()) + " --times 2025-06-21T08:00Z/2025-06-21T09:00Z/PT1H";
    ASSERT_EQ(run(ts_cmd(base)).exit_code, 0);
    const std::map<std::string, std::string> first = snapshot(dir);
    for (const std::string& bad : {std::string(" --overwrite --view perspective --camera 5.75,45.2,-5000,0,-10,60"),
                                   std::string(" --overwrite --times 2025-06-21T22:00Z/2025-06-21T23:00Z/PT1H")}) {
        const Result r = run(ts_cmd(base + bad));
        EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.err;
        EXPECT_EQ(snapshot(dir), first) << bad;
    }
    // A new folder for a refused job is not left behind.
    const fs::path fresh = temp_dir("failed_overwrite_new") / "frames";
    EXPECT_EQ(run(ts_cmd("relight " + quote(kDem) + kCrop + " --out " + quote(fresh.string()) +
                         " --times 2025-06-21T08:00Z/2025-06-21T09:00Z/PT1H --view perspective --camera 5.75,45.2,-5000,0,-10,60"))
                  .exit_code,
              2);
    EXPECT_FALSE(fs::exists(fresh));
}

// A tile set is replaced only by a job whose inputs are read: an unreadable --sky map, or a
// --debug-heights that names no tile of the job, is refused before the folder is touched, and
// a folder made for such a job does not stay.
TEST(OneJobPerOutputCli, ATilesJobWithBadInputsLeavesTheOldSet) {
    const fs::path root = temp_dir("tiles_bad_inputs");
    const fs::path dir = root / "t";
    const std::string base = "tiles " + quote(kDem) + kCrop + " --zoom 9 --out " + quote(dir.string());
    ASSERT_EQ(run(ts_cmd(base)).exit_code, 0);
    const std::map<std::string, std::string> first = snapshot(dir);
    std::ofstream(root / "bad.hdr") << "not a picture";
    for (const std::string& bad : {" --overwrite --sky hdr:" + quote((root / "bad.hdr").string()),
                                   " --overwrite --sky hdr:" + quote((root / "none.hdr").string()),
                                   std::string(" --overwrite --sun-azimuth 200 --debug-heights 99/1/1"),
                                   std::string(" --overwrite --sun-azimuth 200 --debug-heights nine")}) {
        const Result r = run(ts_cmd(base + bad));
        EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.err;
        EXPECT_EQ(snapshot(dir), first) << bad;
    }
    const fs::path fresh = root / "new";
    EXPECT_EQ(run(ts_cmd("tiles " + quote(kDem) + kCrop + " --zoom 9 --out " + quote(fresh.string()) + " --sky hdr:" +
                         quote((root / "bad.hdr").string())))
                  .exit_code,
              2);
    EXPECT_FALSE(fs::exists(fresh));
}

// Two outputs that are one file, however spelt, are refused.
TEST(OneJobPerOutputCli, OneFileIsNotTwoOutputs) {
    const fs::path dir = temp_dir("written_twice");
    const Result r = run("cd " + quote(dir.string()) + " && " +
                         ts_cmd("visibility " + quote(kDem) + kCrop + " --directions 8 --svf a.tif --sky-visible ./a.tif"));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("written twice"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "a.tif"));
}

// A DEM edited in place (same size and place, other heights) is another tile job: its tiles are
// made anew, not resumed from the old DEM's.
TEST(OneJobPerOutputCli, TilesOfAnEditedDemAreNotResumed) {
    const fs::path root = temp_dir("edited_dem");
    const fs::path dem = root / "d.tif", dir = root / "t";
    ASSERT_EQ(run("gdal_translate -q -srcwin 100 100 120 120 " + quote(kDem) + " " + quote(dem.string())).exit_code, 0);
    const std::string cmd = "tiles " + quote(dem.string()) + " --zoom 10 --style hillshade --out " + quote(dir.string());
    ASSERT_EQ(run(ts_cmd(cmd)).exit_code, 0);
    ASSERT_EQ(run("gdal_calc.py --quiet -A " + quote(dem.string()) + " --outfile=" + quote((root / "e.tif").string()) +
                  " --calc=A*2 && mv " + quote((root / "e.tif").string()) + " " + quote(dem.string()))
                  .exit_code,
              0);
    const Result again = run(ts_cmd(cmd));
    EXPECT_EQ(again.exit_code, 2) << again.out << again.err;  // another job: refused without --overwrite
    EXPECT_NE(again.err.find("another job"), std::string::npos) << again.err;
}

}  // namespace
}  // namespace ts::cli_test
