// `terrashade tiles` end to end on the shared DEMs:
//  - seams: the 2x2 block of 256-px tiles at zoom z equals, pixel for pixel, the 512-px tile at
//    z-1 over the same ground (hillshade and relief), so neighbours continue each other exactly;
//  - hillshade equals gdaldem hillshade on the tile's own pixels (GDAL as an oracle only);
//  - MBTiles 1.3: schema, unique index, metadata, TMS rows, the same tiles as XYZ;
//  - resume: after kill -9 at several moments, --resume finishes with every tile's bytes equal
//    to an uninterrupted run, and keeps the tiles that were done;
//  - bad input: exit 2 and one line, before any shading.
#include <fcntl.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.hpp"
#include "tests/cli/frame_pixels.hpp"
#include "tests/cli/mbtiles_probe.hpp"

namespace fs = std::filesystem;
using ts::cli_test::committed_tiles;
using ts::cli_test::Pixels;
using ts::cli_test::read_pixels;
using ts::cli_test::quote;
using ts::cli_test::run;
using ts::cli_test::kSharedDems;
using ts::cli_test::temp_dir;
using ts::cli_test::terrashade;

namespace {

const std::string kGrenoble = kSharedDems + "copernicus_N45E005_grenoble_500px.tif";
const std::string kAnatolia = kSharedDems + "srtm3_N39E040_1000px.tif";

std::string read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::uint64_t fnv1a(const std::string& bytes) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    return h;
}

// "z/x/y" -> content hash, for every tile of an XYZ directory (hidden files skipped).
std::map<std::string, std::uint64_t> xyz_hashes(const fs::path& dir) {
    std::map<std::string, std::uint64_t> out;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        const fs::path key = fs::relative(e.path(), dir);
        // Tiles only: not the job file, temporaries, nor the viewer beside the Z folders.
        if (!e.is_regular_file() || e.path().filename().string()[0] == '.' || !key.has_parent_path()) continue;
        out[key.string()] = fnv1a(read_bytes(e.path()));
    }
    return out;
}

// For a failed comparison of two XYZ folders: each tile that differs, in bytes and in pixels
// (how many differ, by how much, the first one), or which folder lacks it. Tells an encoder
// that is not a function of the pixels from shading that is not a function of the inputs.
std::string xyz_differences(const fs::path& a, const fs::path& b) {
    const auto ha = xyz_hashes(a), hb = xyz_hashes(b);
    std::ostringstream out;
    for (const auto& [key, hash] : ha) {
        const auto it = hb.find(key);
        if (it == hb.end()) {
            out << key << ": only in " << a << "\n";
            continue;
        }
        if (it->second == hash) continue;
        const Pixels pa = read_pixels(a / key), pb = read_pixels(b / key);
        out << key << ": " << fs::file_size(a / key) << " vs " << fs::file_size(b / key) << " bytes";
        if (pa.width != pb.width || pa.height != pb.height || pa.channels != pb.channels || pa.data.empty()) {
            out << ", different or unreadable pictures\n";
            continue;
        }
        std::size_t differing = 0, first = pa.data.size();
        int worst = 0;
        for (std::size_t k = 0; k < pa.data.size(); ++k)
            if (pa.data[k] != pb.data[k]) {
                ++differing, first = std::min(first, k);
                worst = std::max(worst, std::abs(int(pa.data[k]) - int(pb.data[k])));
            }
        out << ", " << differing << " of " << pa.data.size() << " samples differ";
        if (differing) {
            const std::size_t px = first / std::size_t(pa.channels);
            out << " (by up to " << worst << "; first at column " << px % std::size_t(pa.width) << ", row "
                << px / std::size_t(pa.width) << ")";
        }
        out << "\n";
    }
    for (const auto& [key, hash] : hb)
        if (!ha.count(key)) out << key << ": only in " << b << "\n";
    return out.str();
}

// The same for an MBTiles file, keyed "z/x/tmsrow".
std::map<std::string, std::uint64_t> mbtiles_hashes(const fs::path& file) {
    std::map<std::string, std::uint64_t> out;
    sqlite3* db = nullptr;
    if (sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) return out;
    sqlite3_stmt* q = nullptr;
    sqlite3_prepare_v2(db, "SELECT zoom_level, tile_column, tile_row, tile_data FROM tiles", -1, &q, nullptr);
    while (q && sqlite3_step(q) == SQLITE_ROW) {
        const std::string key = std::to_string(sqlite3_column_int(q, 0)) + "/" + std::to_string(sqlite3_column_int(q, 1)) +
                                "/" + std::to_string(sqlite3_column_int(q, 2));
        const auto* blob = static_cast<const char*>(sqlite3_column_blob(q, 3));
        out[key] = fnv1a(std::string(blob, std::size_t(sqlite3_column_bytes(q, 3))));
    }
    sqlite3_finalize(q);
    sqlite3_close(db);
    return out;
}

std::string tiles_cmd(const std::string& dem, const std::string& args, const fs::path& out) {
    return quote(terrashade()) + " tiles " + quote(dem) + " " + args + " --out " + quote(out.string());
}

// Starts terrashade with `args` (split on spaces), without a shell, so kill() hits it.
pid_t spawn(const std::vector<std::string>& args) {
    const pid_t pid = fork();
    if (pid == 0) {
        std::vector<char*> argv;
        for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        const int devnull = ::open("/dev/null", O_WRONLY);
        dup2(devnull, 1), dup2(devnull, 2);
        execv(argv[0], argv.data());
        _exit(127);
    }
    return pid;
}

// Checks the 2x2 block of 256-px tiles at z against the 512-px tiles at z-1, over every 512 tile.
void expect_seamless(const fs::path& small_dir, const fs::path& large_dir, int z) {
    int compared = 0;
    for (const auto& xdir : fs::directory_iterator(large_dir / std::to_string(z - 1)))
        for (const auto& f : fs::directory_iterator(xdir.path())) {
            if (f.path().filename().string()[0] == '.') continue;
            const int x = std::stoi(xdir.path().filename().string()), y = std::stoi(f.path().stem().string());
            const Pixels large = read_pixels(f.path());
            ASSERT_EQ(large.width, 512);
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx) {
                    const fs::path sp = small_dir / std::to_string(z) / std::to_string(2 * x + dx) /
                                        (std::to_string(2 * y + dy) + ".png");
                    // A quarter with no data is not written; then the large tile is clear there.
                    Pixels small;
                    if (fs::exists(sp)) small = read_pixels(sp);
                    long differ = 0;
                    for (int r = 0; r < 256; ++r)
                        for (int c = 0; c < 256; ++c)
                            for (int ch = 0; ch < large.channels; ++ch) {
                                const int a = large.at(dx * 256 + c, dy * 256 + r, ch);
                                const int b = small.width ? small.at(c, r, ch) : 0;
                                differ += a != b;
                            }
                    EXPECT_EQ(differ, 0) << "z" << z << " tile " << 2 * x + dx << "/" << 2 * y + dy;
                    ++compared;
                }
        }
    EXPECT_GE(compared, 4);
}

TEST(TilesCli, HillshadeTwoByTwoEqualsOne512TileOfTheZoomAbove) {
    const fs::path d = temp_dir("seam_hs");
    ASSERT_EQ(run(tiles_cmd(kAnatolia, "--zoom 11 --style hillshade", d / "s256")).exit_code, 0);
    ASSERT_EQ(run(tiles_cmd(kAnatolia, "--zoom 10 --tile-size 512 --style hillshade", d / "s512")).exit_code, 0);
    expect_seamless(d / "s256", d / "s512", 11);
}

TEST(TilesCli, ReliefTwoByTwoEqualsOne512TileOfTheZoomAbove) {
    const fs::path d = temp_dir("seam_relief");
    ASSERT_EQ(run(tiles_cmd(kGrenoble, "--zoom 10 --style relief --directions 8", d / "s256")).exit_code, 0);
    ASSERT_EQ(run(tiles_cmd(kGrenoble, "--zoom 9 --tile-size 512 --style relief --directions 8", d / "s512")).exit_code, 0);
    expect_seamless(d / "s256", d / "s512", 10);
}

// The exaggeration of Anatolia's z12 tiles: that of the DEM's native zoom z10 (docs/tiles.md).
const double kNativeExaggeration = std::exp2(2.0 / 3.0);

TEST(TilesCli, HillshadeRowsEqualGdaldemOnTheTilePixels) {
    // The tile's heights with their 1-px halo, as the tile sampled them, come from
    // `tiles --debug-heights`; gdaldem with the row's Mercator z-factor must give that row.
    const fs::path d = temp_dir("gdaldem");
    const auto r = run(tiles_cmd(kAnatolia, "--zoom 12 --style hillshade --debug-heights 12/2508/1555", d / "t"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const fs::path heights = d / "t" / "12-2508-1555-heights.tif";
    ASSERT_TRUE(fs::exists(heights));
    const Pixels tile = read_pixels(d / "t" / "12" / "2508" / "1555.png");
    ASSERT_EQ(tile.width, 256);
    // Rows 0, 128, 255: z_j = E cosh(y_j / R), y_j the row's pixel centre, E the exaggeration:
    // z12 is past the 90 m DEM's native zoom z10 and keeps E(10) = 2^(2/3).
    for (int j : {0, 128, 255}) {
        const double res = 2 * 20037508.342789244 / (256.0 * 4096);
        const double y = 20037508.342789244 - (1555 * 256 + j + 0.5) * res;
        const double z = kNativeExaggeration * std::cosh(y / 6378137.0);
        char zs[64];
        std::snprintf(zs, sizeof zs, "%.17g", z);
        const fs::path out = d / ("gd" + std::to_string(j) + ".tif");
        ASSERT_EQ(run("gdaldem hillshade -q -az 315 -alt 45 -z " + std::string(zs) + " " + quote(heights.string()) + " " +
                      quote(out.string()))
                      .exit_code,
                  0);
        const Pixels gd = read_pixels(out);
        ASSERT_EQ(gd.width, 258);
        int equal = 0, off_by_one = 0;
        for (int i = 0; i < 256; ++i) {
            const int a = tile.at(i, j, 0), b = gd.at(i + 1, j + 1, 0);
            EXPECT_LE(std::abs(a - b), 1) << "row " << j << " col " << i;
            equal += a == b, off_by_one += std::abs(a - b) == 1;
        }
        // gdaldem uses an approximate 1/sqrt: a value on a rounding boundary may differ by one.
        EXPECT_GE(equal, 250) << "row " << j;
    }
}

TEST(TilesCli, MultidirectionalRowEqualsGdaldemMultidirectional) {
    const fs::path d = temp_dir("gdaldem_md");
    const auto r = run(tiles_cmd(kAnatolia, "--zoom 12 --style multidirectional --debug-heights 12/2508/1555", d / "t"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Pixels tile = read_pixels(d / "t" / "12" / "2508" / "1555.png");
    ASSERT_EQ(tile.width, 256);
    const int j = 128;
    const double res = 2 * 20037508.342789244 / (256.0 * 4096);
    const double y = 20037508.342789244 - (1555 * 256 + j + 0.5) * res;
    char zs[64];
    std::snprintf(zs, sizeof zs, "%.17g", kNativeExaggeration * std::cosh(y / 6378137.0));
    const fs::path out = d / "gd.tif";
    ASSERT_EQ(run("gdaldem hillshade -q -multidirectional -alt 45 -z " + std::string(zs) + " " +
                  quote((d / "t" / "12-2508-1555-heights.tif").string()) + " " + quote(out.string()))
                  .exit_code,
              0);
    const Pixels gd = read_pixels(out);
    ASSERT_EQ(gd.width, 258);
    int equal = 0;
    for (int i = 0; i < 256; ++i) {
        const int a = tile.at(i, j, 0), b = gd.at(i + 1, j + 1, 0);
        EXPECT_LE(std::abs(a - b), 1) << "col " << i;
        equal += a == b;
    }
    EXPECT_GE(equal, 250);
}

TEST(TilesCli, MbtilesSchemaMetadataAndTmsRows) {
    const fs::path d = temp_dir("mbtiles");
    ASSERT_EQ(run(tiles_cmd(kGrenoble, "--zoom 8-10 --style hillshade", d / "t.mbtiles")).exit_code, 0);
    ASSERT_EQ(run(tiles_cmd(kGrenoble, "--zoom 8-10 --style hillshade", d / "xyz")).exit_code, 0);
    EXPECT_FALSE(fs::exists(d / "t.mbtiles.partial"));
    EXPECT_FALSE(fs::exists(d / "t.mbtiles-wal"));
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open_v2((d / "t.mbtiles").c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
    std::map<std::string, std::string> meta;
    sqlite3_stmt* q = nullptr;
    sqlite3_prepare_v2(db, "SELECT name, value FROM metadata", -1, &q, nullptr);
    while (sqlite3_step(q) == SQLITE_ROW)
        meta[reinterpret_cast<const char*>(sqlite3_column_text(q, 0))] = reinterpret_cast<const char*>(sqlite3_column_text(q, 1));
    sqlite3_finalize(q);
    for (const char* key : {"name", "format", "bounds", "center", "minzoom", "maxzoom", "attribution"})
        EXPECT_TRUE(meta.count(key)) << key;
    EXPECT_EQ(meta["format"], "png");
    // The job the tiles were made with (what --resume compares), as JSON a reader can parse.
    ASSERT_TRUE(meta.count("terrashade_job"));
    const auto job = nlohmann::json::parse(meta["terrashade_job"], nullptr, false);
    ASSERT_FALSE(job.is_discarded()) << meta["terrashade_job"];
    EXPECT_EQ(job.value("style", ""), "hillshade");
    EXPECT_TRUE(job.contains("sky"));
    EXPECT_EQ(meta["minzoom"], "8");
    EXPECT_EQ(meta["maxzoom"], "10");
    double w = 0, s = 0, e = 0, n = 0;
    ASSERT_EQ(std::sscanf(meta["bounds"].c_str(), "%lf,%lf,%lf,%lf", &w, &s, &e, &n), 4);
    EXPECT_NEAR(w, 5.0, 0.01);
    EXPECT_NEAR(e, 6.0, 0.01);
    EXPECT_NEAR(s, 45.0, 0.01);
    EXPECT_NEAR(n, 46.0, 0.01);
    // The unique index on (zoom_level, tile_column, tile_row).
    sqlite3_prepare_v2(db, "SELECT sql FROM sqlite_master WHERE type = 'index' AND tbl_name = 'tiles'", -1, &q, nullptr);
    std::string index_sql;
    while (sqlite3_step(q) == SQLITE_ROW) index_sql += reinterpret_cast<const char*>(sqlite3_column_text(q, 0));
    sqlite3_finalize(q);
    EXPECT_NE(index_sql.find("UNIQUE INDEX"), std::string::npos);
    EXPECT_NE(index_sql.find("zoom_level, tile_column, tile_row"), std::string::npos);
    sqlite3_close(db);
    // The same tiles as the XYZ directory, rows flipped (TMS).
    const auto mb = mbtiles_hashes(d / "t.mbtiles");
    const auto xyz = xyz_hashes(d / "xyz");
    EXPECT_EQ(mb.size(), xyz.size());
    for (const auto& [key, hash] : xyz) {
        int z = 0, x = 0, y = 0;
        ASSERT_EQ(std::sscanf(key.c_str(), "%d/%d/%d.png", &z, &x, &y), 3);
        const std::string tms = std::to_string(z) + "/" + std::to_string(x) + "/" + std::to_string((1 << z) - 1 - y);
        ASSERT_TRUE(mb.count(tms)) << tms;
        EXPECT_EQ(mb.at(tms), hash) << key;
    }
}

std::size_t count_files(const fs::path& dir) {
    std::size_t n = 0;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
        n += it->is_regular_file(ec) && it->path().extension() == ".png";
    return n;
}

std::uintmax_t file_size_or_zero(const fs::path& p) {
    std::error_code ec;
    const auto n = fs::file_size(p, ec);
    return ec ? 0 : n;
}

// Runs `args` into `out`, kills it with SIGKILL once `ready()` holds (or after 30 s), then
// resumes; returns the resumed run's stdout. `killed`: whether the kill landed (the run may
// have finished between two polls).
template <class Ready>
std::string kill_and_resume(const std::vector<std::string>& args, const fs::path& out, Ready&& ready,
                            bool* killed = nullptr) {
    std::vector<std::string> full = {terrashade(), "tiles"};
    full.insert(full.end(), args.begin(), args.end());
    full.insert(full.end(), {"--out", out.string()});
    const pid_t pid = spawn(full);
    const auto start = std::chrono::steady_clock::now();
    while (!ready() && std::chrono::steady_clock::now() - start < std::chrono::seconds(30))
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    if (killed) *killed = WIFSIGNALED(status);
    std::string cmd = quote(terrashade()) + " tiles";
    for (const auto& a : args) cmd += " " + quote(a);
    const auto r = run(cmd + " --out " + quote(out.string()) + " --resume");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.out;
}

std::string command_of(const std::vector<std::string>& args) {
    std::string cmd = quote(terrashade()) + " tiles";
    for (const auto& a : args) cmd += " " + quote(a);
    return cmd;
}

TEST(TilesCli, XyzResumeAfterKillEqualsUninterruptedRun) {
    const fs::path d = temp_dir("resume_xyz");
    // relief: the resumed run recomputes the visibility of the zooms still to do; it must give
    // the same bytes.
    // --exaggeration 1: zooms 9-11 share one level-0 source, computed once per run.
    const std::vector<std::string> args = {kGrenoble, "--zoom", "8-11", "--style", "relief", "--directions", "8",
                                           "--exaggeration", "1"};
    ASSERT_EQ(run(command_of(args) + " --out " + quote((d / "whole").string())).exit_code, 0);
    const auto whole = xyz_hashes(d / "whole");
    ASSERT_GT(whole.size(), 20u);
    // Killed while shading the first zoom, and once a third of the tiles are written.
    const fs::path early = d / "early";
    kill_and_resume(args, early, [&] { return fs::exists(early / ".terrashade-tiles.json"); });
    EXPECT_TRUE(xyz_hashes(early) == whole) << "killed early:\n" << xyz_differences(early, d / "whole");
    // A fast machine can write the last tiles between two polls: the run is then repeated and
    // killed at a lower count, until a kill lands while tiles are being written.
    std::string report;
    bool killed = false;
    for (const std::size_t part : {3u, 6u, 20u}) {
        const fs::path late = d / ("late_" + std::to_string(part));
        const std::size_t at = std::max<std::size_t>(1, whole.size() / part);
        report = kill_and_resume(args, late, [&] { return count_files(late) >= at; }, &killed);
        EXPECT_TRUE(xyz_hashes(late) == whole)
            << "killed late, after " << at << " tiles:\n" << xyz_differences(late, d / "whole");
        if (killed) break;
    }
    ASSERT_TRUE(killed) << "every run finished before it was killed";
    EXPECT_EQ(report.find(" 0 resumed"), std::string::npos) << report;
}

TEST(TilesCli, MbtilesResumeAfterKillEqualsUninterruptedRun) {
    const fs::path d = temp_dir("resume_mb");
    const std::vector<std::string> args = {kAnatolia, "--zoom", "9-12", "--style", "hillshade"};
    ASSERT_EQ(run(command_of(args) + " --out " + quote((d / "whole.mbtiles").string())).exit_code, 0);
    const auto whole = mbtiles_hashes(d / "whole.mbtiles");
    ASSERT_GT(whole.size(), 150u);
    const fs::path early = d / "early.mbtiles", late = d / "late.mbtiles";
    kill_and_resume(args, early, [&] { return fs::exists(fs::path(early.string() + ".partial")); });
    EXPECT_FALSE(fs::exists(fs::path(early.string() + ".partial")));
    EXPECT_EQ(mbtiles_hashes(early), whole) << "killed early";
    // Killed once a few batches are committed: counted by a reader of the partial file, as the
    // log's size alone may be a batch spilled before its commit.
    const std::string report =
        kill_and_resume(args, late, [&] { return committed_tiles(late.string() + ".partial") >= 40; });
    EXPECT_FALSE(fs::exists(fs::path(late.string() + ".partial")));
    EXPECT_EQ(mbtiles_hashes(late), whole) << "killed late";
    EXPECT_EQ(report.find(" 0 resumed"), std::string::npos) << report;
}

TEST(TilesCli, AnExistingMbtilesIsNotTouchedUntilTheNewOneIsWhole) {
    const fs::path d = temp_dir("keep_mb");
    const fs::path file = d / "t.mbtiles";
    ASSERT_EQ(run(tiles_cmd(kGrenoble, "--zoom 8 --style hillshade", file)).exit_code, 0);
    const std::string before = read_bytes(file);
    const pid_t pid = spawn({terrashade(), "tiles", kAnatolia, "--zoom", "9-12", "--style", "hillshade", "--overwrite",
                             "--out", file.string()});
    const auto start = std::chrono::steady_clock::now();
    while (file_size_or_zero(file.string() + ".partial-wal") < 1'000'000 &&
           std::chrono::steady_clock::now() - start < std::chrono::seconds(30))
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    EXPECT_EQ(read_bytes(file), before);
}

TEST(TilesCli, BadInputExitsTwoWithOneLine) {
    const fs::path d = temp_dir("bad");
    struct Case {
        std::string args;
        std::string says;
    };
    const std::vector<Case> cases = {
        {"--zoom 25", "0..24"},
        {"--zoom -1", "0..24"},
        {"--zoom 9-7", "Z1 must not be below Z0"},
        {"--zoom 8-x", "Z0-Z1"},
        {"--zoom 8 --tile-size 300", "256 or 512"},
        {"--zoom 8 --style shiny", "--style"},
        {"--zoom 8 --far-field near", "--far-field"},
        {"--zoom 8 --resampling lanczos", "--resampling"},
        {"--zoom 8 --relief-contrast 9", "--relief-contrast"},
        {"--zoom 8 --relief-contrast 0", "--relief-contrast"},
        {"--zoom 8 --style hillshade --relief-contrast 1.5", "--relief-contrast: only the relief style has it"},
        {"--zoom 8 --level-bias 5", "--level-bias"},
        {"--zoom 8 --level-bias x", "--level-bias"},
        {"--zoom 8 --z-factor 0", "--z-factor"},
        {"--zoom 8 --exaggeration much", "--exaggeration"},
        {"--zoom 8 --time 2025-13-01T00:00Z", "month 13"},
        {"--zoom 8 --time 2025-06-21T12:00:00Z --sun-azimuth 10", "not both"},
    };
    for (const Case& c : cases) {
        const auto r = run(tiles_cmd(kGrenoble, c.args, d / "x"));
        EXPECT_EQ(r.exit_code, 2) << c.args;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << ": " << r.err;
    }
    // Unwritable or impossible outputs and missing inputs, each found before the DEM is read
    // (IoPlan): one line naming the path, and nothing created.
    fs::create_directories(d / "a_directory.mbtiles");
    std::ofstream(d / "a_file") << "not a directory";
    const std::vector<Case> paths = {
        {"/proc/terrashade-tiles", "cannot create"},
        {"/nonexistent-dir/t.mbtiles", "does not exist (--out)"},
        {(d / "a_directory.mbtiles").string(), "is a directory"},
        {(d / "a_file").string(), "is a file; --out takes a directory"},
        {(d / "a_file" / "tiles").string(), "is not a directory (--out)"},
    };
    for (const Case& c : paths) {
        const auto r = run(quote(terrashade()) + " tiles " + quote(kGrenoble) + " --zoom 8 --out " + quote(c.args));
        EXPECT_EQ(r.exit_code, 2) << c.args;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << ": " << r.err;
    }
    auto r = run(tiles_cmd("/nonexistent/dem.tif", "--zoom 8", d / "none"));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("no such file (DEM)"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(d / "none"));
    // An unwritable existing directory: refused before any tile, the directory left as it was.
    if (::geteuid() != 0) {
        fs::create_directories(d / "locked");
        fs::permissions(d / "locked", fs::perms::owner_read | fs::perms::owner_exec);
        r = run(tiles_cmd(kGrenoble, "--zoom 8", d / "locked"));
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_NE(r.err.find("cannot write in"), std::string::npos) << r.err;
        fs::permissions(d / "locked", fs::perms::owner_all);
    }
    // A DEM that covers no tile: beyond Web Mercator's 85.05 deg.
    const fs::path polar = d / "polar.tif";
    ASSERT_EQ(run("gdal_translate -q -a_ullr 0 89.9 3 89.0 " + quote(kSharedDems + "nodata_3x3.tif") + " " +
                  quote(polar.string()))
                  .exit_code,
              0);
    r = run(tiles_cmd(polar.string(), "--zoom 3", d / "polar_tiles"));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("covers no"), std::string::npos) << r.err;
    // --resume onto tiles of another job.
    ASSERT_EQ(run(tiles_cmd(kGrenoble, "--zoom 8 --style hillshade", d / "job")).exit_code, 0);
    r = run(tiles_cmd(kGrenoble, "--zoom 8 --style multidirectional --resume", d / "job"));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    // ... and onto relief tiles of another contrast.
    ASSERT_EQ(run(tiles_cmd(kGrenoble, "--zoom 8 --directions 8", d / "relief_job")).exit_code, 0);
    r = run(tiles_cmd(kGrenoble, "--zoom 8 --directions 8 --relief-contrast 1.5 --resume", d / "relief_job"));
    EXPECT_EQ(r.exit_code, 2) << r.err;
}

}  // namespace

namespace ts::cli_test {
namespace {

// bench tiles --knobs (the report's tiles study) on a coarse zoom: every block setting within a
// few sRGB codes of the level shaded whole (RMS), and the 512-px tiles equal to the 256-px ones.
TEST(TilesCli, BenchKnobsBoundBlockErrorsAndFindTileSizesIdentical) {
    const fs::path d = temp_dir("bench_knobs");
    const fs::path csv = d / "knobs.csv";
    const auto r = run(quote(terrashade()) + " bench tiles " + quote(kGrenoble) + " --zoom 7-8 --knobs --csv " +
                       quote(csv.string()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "knob,value,is_default,seconds,rms_codes,max_codes");
    std::map<std::string, int> rows, defaults;
    std::map<std::string, std::map<int, double>> level_rms;  // level_bias_zZ -> bias -> rms codes
    while (std::getline(in, line)) {
        std::stringstream ss(line);
        std::string knob, value, is_default, seconds, rms, worst;
        std::getline(ss, knob, ','), std::getline(ss, value, ','), std::getline(ss, is_default, ',');
        std::getline(ss, seconds, ','), std::getline(ss, rms, ','), std::getline(ss, worst, ',');
        ++rows[knob];
        defaults[knob] += is_default == "1";
        EXPECT_GT(std::stod(seconds), 0.0) << line;
        if (knob.starts_with("level_bias_z"))
            level_rms[knob][std::stoi(value)] = std::stod(rms);
        else if (knob == "tile_size" || value == "whole")
            EXPECT_EQ(std::stod(rms), 0.0) << line;
        else
            EXPECT_LT(std::stod(rms), 2.0) << line;
    }
    // The pyramid level per zoom (here z7: level 2 matched, z8: level 1): each coarser level
    // errs more against level 0's relief averaged to the matched level, and the matched level
    // is within a few codes of it (the prefilter's residue, docs/accuracy.md).
    ASSERT_EQ(level_rms.size(), 2u);
    for (const auto& [knob, by_bias] : level_rms) {
        EXPECT_EQ(defaults[knob], 1) << knob;
        ASSERT_TRUE(by_bias.count(0) && by_bias.count(1) && by_bias.count(-1)) << knob;
        for (const auto& [bias, rms] : by_bias)
            if (bias > 0) {
                EXPECT_GT(rms, by_bias.at(bias - 1)) << knob << " " << bias;
            }
        EXPECT_LT(by_bias.at(0), 20.0) << knob;
    }
    for (const std::string k : {"far_field", "block_halo", "block_texels", "tile_size"}) {
        EXPECT_GE(rows[k], 2) << k;
        EXPECT_EQ(defaults[k], 1) << k;
    }
    EXPECT_EQ(run(quote(terrashade()) + " bench tiles " + quote(kGrenoble) + " --knobs").exit_code, 2);
}


// A global grid goes on across 180 degrees (core/dem/wrap_longitude.hpp): at zoom 2 the relief
// either side of the antimeridian differs no more than neighbouring columns do elsewhere
// (measured: 5.0 codes across it, 4.0 between neighbouring columns; 22.4 when the grid ended).
TEST(TilesCli, AGlobalGridHasNoSeamAtTheAntimeridian) {
    const auto dir = temp_dir("tiles_antimeridian") / "t";
    const Result r = run(ts_cmd("tiles " + quote(kSharedDems + "etopo1_global_1deg.tif") + " --zoom 2 --style relief --out " +
                                quote(dir.string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    double seam = 0, neighbours = 0;
    std::size_t n = 0, m = 0;
    for (int y : {1, 2}) {
        int w = 0, h = 0;
        const auto west = read_rgb(dir / "2" / "0" / (std::to_string(y) + ".png"), w, h);
        const auto east = read_rgb(dir / "2" / "3" / (std::to_string(y) + ".png"), w, h);
        ASSERT_EQ(w, 256);
        for (int j = 0; j < h; ++j) {
            const std::size_t row = std::size_t(j) * std::size_t(w) * 3;
            seam += std::abs(int(west[row]) - int(east[row + 3 * std::size_t(w - 1)])), ++n;
            for (int i = 0; i + 1 < w; ++i)
                neighbours += std::abs(int(west[row + 3 * std::size_t(i)]) - int(west[row + 3 * std::size_t(i + 1)])), ++m;
        }
    }
    EXPECT_LT(seam / double(n), 2.0 * neighbours / double(m)) << "seam " << seam / double(n) << ", neighbours "
                                                              << neighbours / double(m);
}

}  // namespace
}  // namespace ts::cli_test
