// The one options layer (app/options/): every command that takes a shared option shows it with
// the same wording and range in its --help, refuses the same values, and names the flag the
// user typed for an error core/ reports by quantity. And the values that used to pass silently
// (issue "Values that passed silently"): each refused with one line and exit 2.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_support.hpp"
#include "tests/support/shared_data.hpp"

namespace ts::cli_test {
namespace {
namespace fs = std::filesystem;

using ts::test::kCessna;

int lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

// The help entry of `flag` in `help`: its line and the description lines under it, whitespace
// collapsed, the default value ("=32", "=clear") dropped. Empty if
// the command does not take it.
std::string help_entry(const std::string& help, const std::string& flag) {
    std::istringstream in(help);
    std::string line, entry;
    bool inside = false;
    const std::regex starts("^\\s+(-[A-Za-z],\\s*)?" + flag + "(\\s|$)");
    while (std::getline(in, line)) {
        if (inside && (line.empty() || std::regex_search(line, std::regex("^\\s+-")))) break;
        if (!inside && std::regex_search(line, starts)) {
            inside = true;
            // The default ("=32", "=clear") ends the names and type, before the description's gap.
            const std::size_t start = line.find_first_not_of(' ');
            const std::size_t gap = line.find("  ", start);
            std::string names = line.substr(0, gap);
            names = std::regex_replace(names, std::regex("=\\S*$"), "");
            line = names + (gap == std::string::npos ? "" : line.substr(gap));
        }
        if (inside) entry += " " + line;
    }
    entry = std::regex_replace(entry, std::regex("\\s+"), " ");
    return entry;
}

std::vector<std::string> product_commands() {
    std::vector<std::string> c = {"render", "relight", "tiles", "visibility", "hillshade", "spheres", "insolation"};
#ifdef TS_TEST_FLY
    c.push_back("fly");
#endif
    return c;
}

TEST(OptionsCli, EveryCommandShowsTheSharedOptionsWithOneWordingAndRange) {
    // Which commands must take each shared option (fly too in a GPU build).
    std::map<std::string, std::set<std::string>> takes = {
        {"--threads", {"render", "relight", "tiles", "visibility", "hillshade", "spheres", "insolation"}},
        {"--directions", {"render", "relight", "tiles"}},
        {"--sky", {"render", "relight", "tiles"}},
        {"--max-error", {"render", "relight", "tiles"}},
        {"--sun-azimuth", {"render", "tiles"}},
        {"--sun-elevation", {"render", "tiles"}},
        {"--time", {"render", "tiles"}},
        {"--device", {"render", "relight", "visibility", "insolation"}},
        {"--verbose", {"render", "relight", "tiles", "visibility", "insolation"}},
        {"--mesh-forward", {"render", "relight"}},
    };
#ifdef TS_TEST_FLY
    for (const char* f : {"--directions", "--sky", "--mesh-forward", "--verbose", "--time"}) takes[f].insert("fly");
#endif
    // The range each help states.
    const std::map<std::string, std::string> range = {
        {"--threads", "in 0..256"}, {"--directions", "in 4..1024"}, {"--sun-azimuth", "in 0..360"},
        {"--sun-elevation", "in -90..90"}, {"--mesh-forward", "{auto,+x,-x,+y,-y}"}};
    std::map<std::string, std::string> help;
    for (const std::string& c : product_commands()) {
        const Result r = run(ts_cmd(c + " --help"));
        ASSERT_EQ(r.exit_code, 0) << c;
        help[c] = r.out;
    }
    for (const auto& [flag, commands] : takes) {
        std::string first, first_command;
        for (const std::string& c : product_commands()) {
            const std::string entry = help_entry(help[c], flag);
            if (commands.count(c) == 0) continue;
            ASSERT_FALSE(entry.empty()) << c << " --help lacks " << flag;
            if (range.count(flag)) {
                EXPECT_NE(entry.find(range.at(flag)), std::string::npos) << c << ": " << entry;
            }
            if (first.empty()) first = entry, first_command = c;
            EXPECT_EQ(entry, first) << flag << " reads differently in " << c << " and " << first_command;
        }
    }
    // hillshade's --azimuth has the same range as --sun-azimuth.
    EXPECT_NE(help_entry(help["hillshade"], "--azimuth").find("in 0..360"), std::string::npos);
}

TEST(OptionsCli, OutOfRangeSharedValuesAreRefusedByEveryCommand) {
    const fs::path d = temp_dir("options_ranges");
    const std::string dem = quote(kDem) + kCrop;
    const std::string png = quote((d / "x.png").string());
    const std::string cases[] = {
        "render " + dem + kSun + " --threads -1 --out " + png,
        "relight " + dem + " --times 2025-06-21T06:00Z/2025-06-21T08:00Z/PT1H --threads -1 --out " +
            quote((d / "series").string()),
        "tiles " + dem + " --zoom 8 --threads -1 --out " + quote((d / "t").string()),
        "visibility " + dem + " --threads -1 --svf " + png,
        "hillshade " + dem + " --threads -1 --out " + png,
        "spheres " + quote(kCessna) + " --threads -1 --out " + quote((d / "s.json").string()),
        "render " + dem + " --sun-azimuth 400 --sun-elevation 30 --out " + png,
        "tiles " + dem + " --zoom 8 --sun-azimuth 400 --out " + quote((d / "t").string()),
        "hillshade " + dem + " --azimuth 400 --out " + png,
        "render " + dem + kSun + " --directions 2000 --out " + png,
        "tiles " + dem + " --zoom 8 --directions 2 --out " + quote((d / "t").string()),
    };
    for (const std::string& c : cases) {
        const Result r = run(ts_cmd(c));
        EXPECT_EQ(r.exit_code, 2) << c << "\n" << r.err;
        EXPECT_EQ(lines(r.err), 1) << c << "\n" << r.err;
        EXPECT_FALSE(fs::exists(d / "x.png")) << c;
    }
}

TEST(OptionsCli, AnErrorCoreNamesByQuantityNamesTheFlagTheUserTyped) {
    const fs::path d = temp_dir("options_quantity");
    const std::string dem = quote(kDem) + kCrop;
    const std::string png = quote((d / "x.png").string());
    const std::pair<std::string, std::string> cases[] = {
        // The same quantity, two flags: hillshade calls the sun's elevation --altitude.
        {"hillshade " + dem + " --altitude 95 --out " + png, "terrashade: --altitude: must be in [0, 90] degrees, got 95\n"},
        {"render " + dem + kSun + " --exposure 99 --out " + png,
         "terrashade: --exposure 99: give auto or an EV100 number in -10..30\n"},
        {"render " + dem + kSun + " --exp-method nope --out " + png, "terrashade: --exp-method: unknown method 'nope'"},
        {"tiles " + dem + " --zoom 8 --style nope --out " + quote((d / "t").string()), "terrashade: --style nope: use"},
        {"render " + dem + kSun + " --sky cloudy --out " + png, "terrashade: --sky: "},
        {"spheres " + quote(kCessna) + " --count 4 --out " + quote((d / "s.json").string()),
         "terrashade: --count: must be in 8..512"},
        {"render " + dem + kSun + " --mesh " + quote(kCessna) + " --at 5.75,45.2,300agl --spheres 4 --out " + png,
         "--spheres: must be in 8..512"},
    };
    for (const auto& [c, message] : cases) {
        const Result r = run(ts_cmd(c));
        EXPECT_EQ(r.exit_code, 2) << c;
        EXPECT_NE(r.err.find(message), std::string::npos) << c << "\n" << r.err;
        EXPECT_EQ(lines(r.err), 1) << r.err;
    }
}

TEST(OptionsCli, AGeographicExtentBeyondThePolesIsRefused) {
    const fs::path d = temp_dir("options_extent");
    const fs::path out = d / "x.png";
    const Result r = run(ts_cmd("render " + quote(kDem) + kSun + " --directions 8 --extent 5,45,6,95 --extent-crs EPSG:4326 --out " +
                                quote(out.string())));
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("terrashade: --extent: latitudes must be within -90..90"), std::string::npos) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
    // Off the DEM entirely: refused too.
    const Result off = run(ts_cmd("render " + quote(kDem) + kSun + " --directions 8 --extent 10,10,11,11 --extent-crs EPSG:4326 --out " +
                                  quote(out.string())));
    EXPECT_EQ(off.exit_code, 2);
    EXPECT_NE(off.err.find("--extent: the extent does not overlap the DEM"), std::string::npos) << off.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST(OptionsCli, ATilesFolderNamedLikeAPictureIsRefused) {
    const fs::path d = temp_dir("options_tiles_out");
    const Result r = run(ts_cmd("tiles " + quote(kDem) + kCrop + " --zoom 8 --style hillshade --out " +
                                quote((d / "t.png").string())));
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(".png"), std::string::npos) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(d / "t.png"));
}

TEST(OptionsCli, TilesTakesVerbose) {
    const fs::path d = temp_dir("options_tiles_v");
    const Result r = run(ts_cmd("tiles " + quote(kDem) + kCrop + " --zoom 8 --style hillshade -v --out " +
                                quote((d / "t").string())));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("zoom 8: DEM level"), std::string::npos) << r.out;
}

TEST(OptionsCli, TheSvfQuickLookLinePrintsTheFinalName) {
    const fs::path d = temp_dir("options_svf");
    const fs::path out = d / "svf.png";
    const Result r = run(ts_cmd("visibility " + quote(kDem) + kCrop + " --directions 8 --svf " + quote(out.string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find(out.string() + ": grey 1..255"), std::string::npos) << r.out;
    // Every path it prints is the output's.
    std::istringstream in(r.out);
    for (std::string line; std::getline(in, line);)
        if (line.find(d.string()) != std::string::npos) {
            EXPECT_NE(line.find(out.string()), std::string::npos) << "a temporary name: " << line;
        }
}

TEST(OptionsCli, TheRelightLimitIsTheUserGuidesOne) {
    const fs::path d = temp_dir("options_relight_limit");
    // 10001 times, one a minute.
    const Result r = run(ts_cmd("relight " + quote(kDem) + kCrop + " --times 2025-01-01T00:00Z/2025-01-07T22:40Z/PT1M --out " +
                                quote((d / "series").string())));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("10000"), std::string::npos) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    std::ifstream guide(std::string(TS_SOURCE_DIR) + "/docs/user-guide.md");
    const std::string text((std::istreambuf_iterator<char>(guide)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("more than 10000 times"), std::string::npos);
    EXPECT_EQ(text.find("more than 100000 times"), std::string::npos);
}

TEST(OptionsCli, VerboseSaysWhichMeshAxisIsForward) {
    const fs::path d = temp_dir("options_mesh_forward");
    const Result r = run(ts_cmd("render " + quote(kDem) + kCrop + kSun + " --directions 8 --size 64x64 --mesh " +
                                quote(kCessna) + " --at 5.75,45.2,300agl --hpr 90,0,0 --spheres 8 --sphere-cache-dir " +
                                quote((d / "cache").string()) + " -v --out " + quote((d / "x.png").string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("forward axis -x (auto: FlightGear's AC3D nose)"), std::string::npos) << r.out;
    const Result bad = run(ts_cmd("render " + quote(kDem) + kCrop + kSun + " --mesh " + quote(kCessna) +
                                  " --at 5.75,45.2,300agl --mesh-forward z --out " + quote((d / "y.png").string())));
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("--mesh-forward"), std::string::npos) << bad.err;
}

#ifdef TS_TEST_FLY
TEST(OptionsCli, FlyRefusesZeroFramesBinaryPathsAndPathsUnderTheTerrain) {
    const fs::path d = temp_dir("options_fly");
    const std::string base = "fly " + quote(kDem) + " --size 64x36 --directions 8 --out " + quote((d / "frames").string());
    const Result zero = run("env -u DISPLAY -u WAYLAND_DISPLAY " + ts_cmd(base + " --frames 0"));
    EXPECT_EQ(zero.exit_code, 2);
    EXPECT_NE(zero.err.find("--frames 0"), std::string::npos) << zero.err;
    EXPECT_EQ(zero.err.find("display"), std::string::npos) << zero.err;

    const fs::path binary = d / "binary.csv";
    {
        std::ofstream f(binary, std::ios::binary);
        for (int i = 0; i < 300; ++i) f.put(char((i * 37 + 1) % 256 == '\n' ? 1 : (i * 37 + 1) % 256));
    }
    const Result bin = run(ts_cmd(base + " --frames 1 --path " + quote(binary.string())));
    EXPECT_EQ(bin.exit_code, 2);
    EXPECT_EQ(lines(bin.err), 1) << bin.err;
    EXPECT_LT(bin.err.size(), binary.string().size() + 200) << bin.err;
    for (unsigned char c : bin.err) EXPECT_TRUE(c == '\n' || (c >= 0x20 && c < 0x7f)) << int(c);

    const fs::path low = d / "low.csv";
    std::ofstream(low) << "t_s,lon,lat,height_m,heading_deg,pitch_deg,roll_deg\n"
                          "0,5.70,45.15,3000,0,0,0\n"
                          "5,5.72,45.16,100,0,0,0\n";
    const Result under = run(ts_cmd(base + " --frames 2 --path " + quote(low.string())));
    EXPECT_EQ(under.exit_code, 2) << under.out;
    EXPECT_NE(under.err.find("pose 2 (t_s 5)"), std::string::npos) << under.err;
    EXPECT_NE(under.err.find("below the terrain"), std::string::npos) << under.err;
    EXPECT_FALSE(fs::exists(d / "frames" / "frame_0000.png"));
}
#endif

}  // namespace
}  // namespace ts::cli_test
