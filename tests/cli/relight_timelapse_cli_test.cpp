// `terrashade relight` as a time-lapse: frame names carry their instant, times.csv lists every
// frame, automatic exposure follows the day without flicker (dawn readable, night dark),
// night instants are left out unless --night include, --exposure fixes one exposure.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_support.hpp"
#include "tests/cli/frame_pixels.hpp"

namespace ts::cli_test {
namespace {

// A June day at Grenoble, every 2 hours: 02Z and 20Z are in twilight or night (sun -14 and -5
// degrees), 04Z just after sunrise (+1), 12Z near the highest sun (68).
const std::string kDay = " --times 2025-06-21T02:00:00Z/2025-06-21T20:00:00Z/PT2H --directions 8";

struct CsvRow {
    std::string file, time;
    double azimuth = 0, elevation = 0, ev100 = 0;
};

std::vector<CsvRow> read_times_csv(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "frame,file,time_utc,sun_azimuth_deg,sun_elevation_deg,ev100");
    std::vector<CsvRow> rows;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream ss(line);
        for (std::string cell; std::getline(ss, cell, ',');) f.push_back(cell);
        EXPECT_EQ(f.size(), 6u) << line;
        if (f.size() != 6) continue;
        EXPECT_EQ(std::stoul(f[0]), rows.size());
        rows.push_back({f[1], f[2], std::stod(f[3]), std::stod(f[4]), std::stod(f[5])});
    }
    return rows;
}

// Mean of the 8-bit channels (0..255) of a PNG.
double mean_code(const std::filesystem::path& p) {
    const Pixels px = read_pixels(p);
    EXPECT_GT(px.width, 0) << p;
    if (px.width == 0) return -1;
    double sum = 0;
    for (unsigned char c : px.data) sum += c;
    return sum / double(px.data.size());
}

TEST(RelightTimeLapse, NamesCarryTheInstantAndTimesCsvListsEveryFrame) {
    const auto dir = temp_dir("timelapse_names") / "frames";
    const Result r = run(ts_cmd("relight " + quote(kDem) + kCrop + kDay + " --night include --out " + quote(dir.string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<CsvRow> rows = read_times_csv(dir / "times.csv");
    ASSERT_EQ(rows.size(), 10u);
    EXPECT_EQ(rows[0].file, "frame_0000_2025-06-21T0200Z.png");
    EXPECT_EQ(rows[0].time, "2025-06-21T02:00:00Z");
    EXPECT_EQ(rows[9].file, "frame_0009_2025-06-21T2000Z.png");
    for (const CsvRow& row : rows) {
        EXPECT_TRUE(std::filesystem::exists(dir / row.file)) << row.file;
        EXPECT_GE(row.azimuth, 0.0);
        EXPECT_LT(row.azimuth, 360.0);
    }
    EXPECT_LT(rows[0].elevation, -6.0);
    EXPECT_GT(rows[5].elevation, 60.0);
    EXPECT_NE(r.out.find("exposure: automatic per frame"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("times.csv"), std::string::npos) << r.out;
}

// Auto exposure per frame, bounded and averaged: a frame just after sunrise is readable (not
// near-black, as one exposure from the noon frame made it), night stays darker than day, and in
// a dense series the exposure changes gradually.
TEST(RelightTimeLapse, AutoExposureFollowsTheDayWithoutFlicker) {
    const auto dir = temp_dir("timelapse_exposure") / "frames";
    const Result r = run(ts_cmd("relight " + quote(kDem) + kCrop + kDay + " --night include --out " + quote(dir.string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<CsvRow> rows = read_times_csv(dir / "times.csv");
    ASSERT_EQ(rows.size(), 10u);
    const double dawn = mean_code(dir / rows[1].file), noon = mean_code(dir / rows[5].file);
    const double night = mean_code(dir / rows[0].file);
    EXPECT_GT(dawn, 0.5 * noon) << "dawn " << dawn << " noon " << noon;
    EXPECT_LT(night, 0.5 * dawn) << "night " << night << " dawn " << dawn;
    // Frames two hours apart keep their own exposure: no bound on their steps here (the dense
    // series below is where flicker would show).
    // At most 10 EV brighter than the highest sun's exposure (the default --exposure-boost).
    double highest = rows[0].ev100;
    for (const CsvRow& row : rows) highest = std::max(highest, row.ev100);
    for (const CsvRow& row : rows) EXPECT_GE(row.ev100, highest - 10.0 - 0.01) << row.file;

    // A fixed exposure is the same for every frame.
    const auto fixed = dir.parent_path() / "fixed";
    const Result f = run(ts_cmd("relight " + quote(kDem) + kCrop + kDay + " --night include --exposure 14 --out " +
                                quote(fixed.string())));
    ASSERT_EQ(f.exit_code, 0) << f.err;
    for (const CsvRow& row : read_times_csv(fixed / "times.csv")) EXPECT_DOUBLE_EQ(row.ev100, 14.0) << row.file;

    // Every 5 minutes through the evening (the sun from 13 to 3 degrees): the exposure follows
    // the falling light one way, with no step back (flicker), and by at most 0.3 EV a frame
    // (measured: up to 0.23 at 18:50, where the physical sky dims fastest).
    const auto dense = dir.parent_path() / "dense";
    const Result d = run(ts_cmd("relight " + quote(kDem) + kCrop +
                                " --times 2025-06-21T18:00:00Z/2025-06-21T19:00:00Z/PT5M --directions 8 --out " +
                                quote(dense.string())));
    ASSERT_EQ(d.exit_code, 0) << d.err;
    const std::vector<CsvRow> evening = read_times_csv(dense / "times.csv");
    ASSERT_EQ(evening.size(), 13u);
    for (std::size_t k = 1; k < evening.size(); ++k) {
        EXPECT_LE(evening[k].ev100, evening[k - 1].ev100 + 1e-3) << evening[k].time;
        EXPECT_LE(evening[k - 1].ev100 - evening[k].ev100, 0.3) << evening[k].time;
    }
}

// The physical sky's dawn and twilight are as dark as real ones (6 and 13 EV under noon): the
// default 10 EV of brightening shows the dawn at its own exposure and the twilight a dark blue;
// --exposure-boost 3 (what suits Preetham's sky) leaves both dark; only automatic exposure takes it.
TEST(RelightTimeLapse, ExposureBoostLightsAPhysicalTwilight) {
    const auto base = temp_dir("timelapse_boost");
    const std::string day = kDay + " --night include";
    const Result d = run(ts_cmd("relight " + quote(kDem) + kCrop + day + " --out " + quote((base / "default").string())));
    ASSERT_EQ(d.exit_code, 0) << d.err;
    EXPECT_NE(d.out.find("at most 10 EV brighter"), std::string::npos) << d.out;
    const Result b = run(ts_cmd("relight " + quote(kDem) + kCrop + day + " --exposure-boost 3 --out " +
                                quote((base / "narrow").string())));
    ASSERT_EQ(b.exit_code, 0) << b.err;
    EXPECT_NE(b.out.find("at most 3 EV brighter"), std::string::npos) << b.out;
    const std::vector<CsvRow> rows = read_times_csv(base / "default" / "times.csv");
    ASSERT_EQ(rows.size(), 10u);
    // Frame 1: the sun 1 degree up; frame 9: 5 degrees down; frame 5: noon. Measured: dawn 131,
    // noon 128, twilight 25 (with 3 EV: 19 and 0).
    const double noon = mean_code(base / "default" / rows[5].file);
    EXPECT_GT(mean_code(base / "default" / rows[1].file), 0.8 * noon);
    EXPECT_LT(mean_code(base / "narrow" / rows[1].file), 0.5 * noon);
    EXPECT_GT(mean_code(base / "default" / rows[9].file), 10.0);  // a blue twilight, not black
    EXPECT_LT(mean_code(base / "narrow" / rows[9].file), 2.0);
    EXPECT_LT(mean_code(base / "default" / rows[0].file), 2.0);  // the night, 14 degrees down

    const Result fixed = run(ts_cmd("relight " + quote(kDem) + kCrop + kDay + " --exposure 14 --exposure-boost 5 --out " +
                                    quote((base / "fixed").string())));
    EXPECT_NE(fixed.exit_code, 0);
    EXPECT_NE(fixed.err.find("--exposure-boost: only with automatic exposure"), std::string::npos) << fixed.err;
    EXPECT_FALSE(std::filesystem::exists(base / "fixed"));
}

TEST(RelightTimeLapse, NightInstantsAreLeftOutByDefault) {
    const auto dir = temp_dir("timelapse_skip") / "frames";
    const Result r = run(ts_cmd("relight " + quote(kDem) + kCrop + kDay + " --out " + quote(dir.string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<CsvRow> rows = read_times_csv(dir / "times.csv");
    ASSERT_EQ(rows.size(), 9u);  // 02Z (sun -14 degrees) left out; 20Z (-5) is civil twilight, kept
    EXPECT_EQ(rows[0].file, "frame_0000_2025-06-21T0400Z.png");
    for (const CsvRow& row : rows) EXPECT_GE(row.elevation, -6.0);
    EXPECT_NE(r.out.find("skipping 1 of 10 instants at night"), std::string::npos) << r.out;
    int pngs = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) pngs += e.path().extension() == ".png";
    EXPECT_EQ(pngs, 9);

    // Only night: nothing to do, said before any work, nothing written.
    const auto none = dir.parent_path() / "none";
    const Result n = run(ts_cmd("relight " + quote(kDem) + kCrop +
                                " --times 2025-06-21T00:00:00Z/2025-06-21T01:00:00Z/PT30M --out " +
                                quote(none.string())));
    EXPECT_EQ(n.exit_code, 2) << n.err;
    EXPECT_NE(n.err.find("night"), std::string::npos) << n.err;
    EXPECT_EQ(std::count(n.err.begin(), n.err.end(), '\n'), 1) << n.err;
    EXPECT_TRUE(!std::filesystem::exists(none) || std::filesystem::is_empty(none));

    // The earlier spelling still works; it and --night include contradict.
    const auto old = dir.parent_path() / "old_flag";
    const Result o = run(ts_cmd("relight " + quote(kDem) + kCrop + kDay + " --skip-night --out " + quote(old.string())));
    ASSERT_EQ(o.exit_code, 0) << o.err;
    EXPECT_EQ(read_times_csv(old / "times.csv").size(), 9u);
    const Result both = run(ts_cmd("relight " + quote(kDem) + kCrop + kDay + " --skip-night --night include --out " +
                                   quote((dir.parent_path() / "both").string())));
    EXPECT_EQ(both.exit_code, 2) << both.err;
}

// A morning and an evening at the same sun get the same exposure (a centred average over frames,
// core/render/sequence_exposure.hpp; the running average before made mornings 0.6 EV brighter).
TEST(RelightTimeLapse, ExposureIsSymmetricInTime) {
    const auto dir = temp_dir("timelapse_symmetric") / "frames";
    // Solar noon at Grenoble is ~11:38Z: frames every hour from 05:38Z to 17:38Z are in pairs
    // of equal sun elevation.
    const Result r = run(ts_cmd("relight " + quote(kDem) + kCrop +
                                " --times 2025-06-21T05:38:00Z/2025-06-21T17:38:00Z/PT1H --directions 8 --out " +
                                quote(dir.string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<CsvRow> rows = read_times_csv(dir / "times.csv");
    ASSERT_EQ(rows.size(), 13u);
    for (std::size_t k = 0; k < 6; ++k) {
        const CsvRow &morning = rows[k], &evening = rows[12 - k];
        EXPECT_NEAR(morning.elevation, evening.elevation, 1.0) << morning.time << " " << evening.time;
        EXPECT_NEAR(morning.ev100, evening.ev100, 1.0 / 3.0) << morning.time << " " << evening.time;
    }
}

}  // namespace
}  // namespace ts::cli_test
