// `terrashade fly`: a short path over the shared Grenoble DEM rendered offscreen (--frames) with
// the validation layer on, the HUD drawn over those frames, the window opened and closed under
// xvfb-run, the one-line message without a display, and bad input found before any work.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "cli_support.hpp"
#include "frame_pixels.hpp"
#include "tests/support/shared_data.hpp"

namespace ts::cli_test {
namespace {

const std::string kCopernicusGrenoble = kSharedDems + "copernicus_N45E005_grenoble_500px.tif";
using ts::test::kCessna;

std::filesystem::path write_path(const std::filesystem::path& dir) {
    const auto p = dir / "path.csv";
    std::ofstream(p) << "t_s,lon,lat,height_m,heading_deg,pitch_deg,roll_deg\n"
                        "0,5.55,45.08,2500,45,-5,0\n"
                        "6,5.62,45.13,2300,50,-8,10\n"
                        "12,5.70,45.18,2200,60,-8,0\n";
    return p;
}

TEST(FlyCli, FramesOfAPathAreWrittenAndChange) {
    ASSERT_TRUE(std::filesystem::exists(kCessna)) << "the shared meshes are missing: " << kCessna;
    const auto dir = temp_dir("fly_frames");
    const auto out = dir / "frames";
    const Result r = run("TERRASHADE_VALIDATION=1 " +
                         ts_cmd("fly " + quote(kCopernicusGrenoble) + " --frames 3 --size 320x180 --directions 8 --path " +
                                quote(write_path(dir).string()) + " --mesh " + quote(kCessna) +
                                " --mesh-forward -x --sphere-cache-dir " + quote((dir / "cache").string()) +
                                " --out " + quote(out.string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("validation:"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("wrote 3 frames"), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(out / "frames.csv"));
    std::vector<unsigned char> previous;
    for (int i = 0; i < 3; ++i) {
        int w = 0, h = 0;
        const auto px = read_rgb(out / ("frame_000" + std::to_string(i) + ".png"), w, h);
        ASSERT_EQ(w, 320);
        ASSERT_EQ(h, 180);
        double mean = 0;
        for (unsigned char v : px) mean += v;
        mean /= double(px.size());
        EXPECT_GT(mean, 30.0) << "frame " << i << " is black";
        // The top row is the bright day sky, the bottom row darker ground.
        double top = 0, bottom = 0;
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                top += px[3 * std::size_t(x) + std::size_t(c)],
                    bottom += px[3 * (std::size_t(h - 1) * std::size_t(w) + std::size_t(x)) + std::size_t(c)];
        EXPECT_GT(top / (3.0 * w), 150.0) << "frame " << i << ": no sky at the top";
        EXPECT_LT(bottom, top) << "frame " << i << ": no ground at the bottom";
        if (!previous.empty()) {
            double diff = 0;
            for (std::size_t k = 0; k < px.size(); ++k) diff += std::abs(int(px[k]) - int(previous[k]));
            EXPECT_GT(diff / double(px.size()), 2.0) << "frame " << i << " equals the one before";
        }
        previous = px;
    }
    // The Cessna, chased from 60 m behind, is what differs from the same frame without it: a
    // small patch in the middle of the picture.
    const auto bare = dir / "bare";
    const Result b = run(ts_cmd("fly " + quote(kCopernicusGrenoble) + " --frames 3 --size 320x180 --directions 8 --path " +
                                quote(write_path(dir).string()) + " --out " + quote(bare.string())));
    ASSERT_EQ(b.exit_code, 0) << b.err;
    int w = 0, h = 0;
    const auto with = read_rgb(out / "frame_0001.png", w, h);
    const auto without = read_rgb(bare / "frame_0001.png", w, h);
    ASSERT_EQ(with.size(), without.size());
    double cx = 0, cy = 0;
    int changed = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = 3 * (std::size_t(y) * std::size_t(w) + std::size_t(x));
            const int d = std::abs(with[i] - without[i]) + std::abs(with[i + 1] - without[i + 1]) +
                          std::abs(with[i + 2] - without[i + 2]);
            if (d > 30) ++changed, cx += x, cy += y;
        }
    ASSERT_GT(changed, 30) << "the aircraft is not drawn";
    EXPECT_LT(changed, w * h / 10) << "the aircraft covers too much";
    EXPECT_NEAR(cx / changed, w / 2.0, 0.15 * w);
    EXPECT_NEAR(cy / changed, h / 2.0, 0.2 * h);

    // Another flight into the same folder would mix two series under one frames.csv: refused at
    // once, the first left as it was.
    const auto csv_before = std::filesystem::last_write_time(bare / "frames.csv");
    const Result again = run(ts_cmd("fly " + quote(kCopernicusGrenoble) + " --frames 2 --size 160x90 --directions 8 --out " +
                                    quote(bare.string())));
    EXPECT_EQ(again.exit_code, 2) << again.err;
    EXPECT_NE(again.err.find("another flight"), std::string::npos) << again.err;
    EXPECT_EQ(std::filesystem::last_write_time(bare / "frames.csv"), csv_before);
    EXPECT_TRUE(std::filesystem::exists(bare / "frame_0002.png"));
}

// --hud on draws the HUD over the same frame: a dark box with near-white text in the top-left
// corner, every other pixel as without it (--frames defaults to no HUD, so the frames above
// are unaffected).
TEST(FlyCli, TheHudIsDrawnInTheTopLeftCornerOnly) {
    const auto dir = temp_dir("fly_hud");
    const std::string args = "fly " + quote(kCopernicusGrenoble) + " --frames 2 --size 480x270 --directions 8 --path " +
                             quote(write_path(dir).string()) + " --out ";
    const Result on = run("TERRASHADE_VALIDATION=1 " + ts_cmd(args + quote((dir / "on").string()) + " --hud on"));
    ASSERT_EQ(on.exit_code, 0) << on.err;
    EXPECT_EQ(on.err.find("validation:"), std::string::npos) << on.err;
    const Result off = run(ts_cmd(args + quote((dir / "off").string())));
    ASSERT_EQ(off.exit_code, 0) << off.err;
    for (const char* frame : {"frame_0000.png", "frame_0001.png"}) {
        int w = 0, h = 0;
        const auto with = read_rgb(dir / "on" / frame, w, h);
        const auto without = read_rgb(dir / "off" / frame, w, h);
        ASSERT_EQ(with.size(), without.size());
        int x0 = w, y0 = h, x1 = -1, y1 = -1, white = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const std::size_t i = 3 * (std::size_t(y) * std::size_t(w) + std::size_t(x));
                bool differs = false, text = true;
                for (int c = 0; c < 3; ++c) {
                    differs |= with[i + std::size_t(c)] != without[i + std::size_t(c)];
                    text &= with[i + std::size_t(c)] >= 225;
                }
                if (!differs) continue;
                x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
                white += text ? 1 : 0;
            }
        // Three lines of text at 1x (the frame is narrower than 1200 px) on their box.
        EXPECT_GE(x0, 4) << frame;
        EXPECT_GE(y0, 4) << frame;
        EXPECT_LT(y1, 60) << frame << ": the HUD reaches down to row " << y1;
        EXPECT_GT(y1 - y0, 30) << frame;
        EXPECT_GT(x1 - x0, 200) << frame;
        EXPECT_LT(x1, w * 85 / 100) << frame << ": the HUD reaches across to column " << x1;
        EXPECT_GT(white, 300) << frame << ": no near-white text";
    }
}

TEST(FlyCli, WithoutADisplayOneLinePointsToFrames) {
    const Result r = run("env -u DISPLAY -u WAYLAND_DISPLAY " + ts_cmd("fly " + quote(kCopernicusGrenoble)));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("--frames"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// With the Cessna and its shadows, so their buffers go through the window's frames too.
TEST(FlyCli, TheWindowOpensAndClosesUnderXvfb) {
    // The window test is part of the suite: without xvfb-run it fails (scripts/setup.sh installs xvfb).
    ASSERT_EQ(run("command -v xvfb-run").exit_code, 0) << "xvfb-run is missing: install xvfb (scripts/setup.sh)";
    const auto dir = temp_dir("fly_window");
    // xvfb-run -a takes the first free display from -n on; two runs starting together (another
    // test binary, another checkout) can race for it, so each starts from its own number, and
    // a lost race (the server gone under us) is tried once more.
    const std::string server = std::to_string(200 + int(::getpid() % 500));
    const std::string command = "TERRASHADE_VALIDATION=1 xvfb-run -a -n " + server + " -s '-screen 0 1024x768x24' " +
                                ts_cmd("fly " + quote(kCopernicusGrenoble) +
                                       " --size 320x180 --directions 8 --exit-after 5 --vsync off --path " +
                                       quote(write_path(dir).string()) + " --mesh " + quote(kCessna) +
                                       " --mesh-forward -x --sphere-cache-dir " + quote((dir / "cache").string()));
    Result r = run(command);
    if (r.exit_code == 2 && r.err.find("cannot open a window") != std::string::npos) r = run(command);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(r.err.find("validation:"), std::string::npos) << r.err;
}

// The same with the DEM streamed by tile: the worker thread loads tiles while the window draws,
// and stops with it.
TEST(FlyCli, AStreamedDemFliesInTheWindowUnderXvfb) {
    ASSERT_EQ(run("command -v xvfb-run").exit_code, 0) << "xvfb-run is missing: install xvfb (scripts/setup.sh)";
    const auto dir = temp_dir("fly_window_stream");
    const std::string server = std::to_string(700 + int(::getpid() % 500));
    const std::string command = "TERRASHADE_VALIDATION=1 xvfb-run -a -n " + server + " -s '-screen 0 1024x768x24' " +
                                ts_cmd("fly " + quote(kCopernicusGrenoble) +
                                       " --stream on --memory-budget 256 --size 320x180 --directions 8 --exit-after 8"
                                       " --vsync off --path " + quote(write_path(dir).string()) + " --mesh " +
                                       quote(kCessna) + " --mesh-forward -x --sphere-cache-dir " +
                                       quote((dir / "cache").string()));
    Result r = run(command);
    if (r.exit_code == 2 && r.err.find("cannot open a window") != std::string::npos) r = run(command);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("streaming"), std::string::npos) << r.out;
    EXPECT_EQ(r.err.find("validation:"), std::string::npos) << r.err;
}

TEST(FlyCli, StreamingFlagsAreCheckedBeforeWork) {
    const auto dir = temp_dir("fly_stream_bad");
    const std::string frames = " --frames 2 --out " + quote(dir.string());
    for (const std::string& flags : {std::string(" --stream maybe"), std::string(" --memory-budget 10"),
                                     std::string(" --overview-level 13"), std::string(" --stream on --crop 5.6,45.1,5.8,45.3"),
                                     std::string(" --stream on --max-error 0.05"), std::string(" --stream on --no-fill")}) {
        const Result r = run(ts_cmd("fly " + quote(kCopernicusGrenoble) + frames + flags));
        EXPECT_EQ(r.exit_code, 2) << flags << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << flags << ": " << r.err;
    }
    // A budget that holds fewer than four detail tiles says how much it needs.
    const Result tight = run(ts_cmd("fly " + quote(kCopernicusGrenoble) + frames + " --stream on --memory-budget 64 --overview-level 2"));
    EXPECT_EQ(tight.exit_code, 2) << tight.err;
    EXPECT_NE(tight.err.find("--memory-budget"), std::string::npos) << tight.err;
}

TEST(FlyCli, BadInputExitsTwoBeforeWork) {
    const auto dir = temp_dir("fly_bad");
    const Result no_out = run(ts_cmd("fly " + quote(kCopernicusGrenoble) + " --frames 2"));
    EXPECT_EQ(no_out.exit_code, 2);
    EXPECT_NE(no_out.err.find("--out"), std::string::npos) << no_out.err;
    const Result size = run(ts_cmd("fly " + quote(kCopernicusGrenoble) + " --frames 2 --out " + quote(dir.string()) + " --size 12"));
    EXPECT_EQ(size.exit_code, 2);
    EXPECT_NE(size.err.find("--size"), std::string::npos) << size.err;
    // The path lies beside the output folder: one inside it is refused as an input the output could clear.
    const auto bad = temp_dir("fly_bad_path") / "bad.csv";
    std::ofstream(bad) << "0,5.6,45.1,2000,0,0\n";
    const Result path = run(ts_cmd("fly " + quote(kCopernicusGrenoble) + " --frames 2 --out " + quote(dir.string()) + " --path " +
                                   quote(bad.string())));
    EXPECT_EQ(path.exit_code, 2);
    EXPECT_NE(path.err.find("7 numbers"), std::string::npos) << path.err;
    const Result spheres = run(ts_cmd("fly " + quote(kCopernicusGrenoble) + " --frames 2 --out " + quote(dir.string()) + " --mesh " +
                                      quote(kCessna) + " --spheres 4"));
    EXPECT_EQ(spheres.exit_code, 2);
    EXPECT_NE(spheres.err.find("--spheres"), std::string::npos) << spheres.err;
    EXPECT_EQ(std::count(spheres.err.begin(), spheres.err.end(), '\n'), 1) << spheres.err;
}

TEST(FlyCli, HelpListsTheKeys) {
    const Result r = run(ts_cmd("fly --help"));
    EXPECT_EQ(r.exit_code, 0);
    for (const char* key : {"Esc", "W/S", "screenshot", "recording", "time of day", "HUD", "--hud"})
        EXPECT_NE(r.out.find(key), std::string::npos) << key;
}

}  // namespace
}  // namespace ts::cli_test
