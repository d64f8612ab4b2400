// --max-error through the commands: render, relight, tiles (and fly, with a GPU) print the one
// line of what they chose and why and use it; E <= 0 and an explicit quality flag beside
// --max-error are refused with one line and exit 2 before any work.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/cli/cli_support.hpp"

namespace ts::cli_test {
namespace {

// The chosen line: "--max-error E: D directions, sun shadows ... (predicted ...)".
bool has_choice_line(const std::string& out, const std::string& e) {
    return out.find("--max-error " + e + ": ") != std::string::npos && out.find(" directions, sun shadows ") != std::string::npos &&
           out.find("predicted relative radiance error") != std::string::npos;
}

TEST(MaxErrorCli, RenderPrintsWhatItChoseAndUsesIt) {
    const auto dir = temp_dir("max_error_render");
    const Result r = run(ts_cmd("render " + quote(kDem) + kCrop +
                                " --sun-azimuth 200 --sun-elevation 30 --max-error 0.06 --out " +
                                quote((dir / "r.png").string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(has_choice_line(r.out, "0.06")) << r.out;
    // The frame's line names the directions chosen.
    const auto at = r.out.find("--max-error 0.06: ");
    ASSERT_NE(at, std::string::npos);
    const int d = std::stoi(r.out.substr(at + 18));
    EXPECT_NE(r.out.find("(" + std::to_string(d) + " directions"), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(dir / "r.png"));
}

// With a mesh: the spheres are chosen with the terrain's setting. When the spheres cast the sun
// shadow their outline is most of the error, so a looser bound takes fewer; when the triangles
// cast it (the default) the error hardly depends on the count, so the fewest serve any bound.
int chosen_spheres(const std::string& out) {
    const std::string key = "--max-error: ";
    const auto at = out.find(key);
    if (at == std::string::npos || out.find(" spheres for the mesh (predicted ", at) == std::string::npos) return -1;
    return std::stoi(out.substr(at + key.size()));
}

TEST(MaxErrorCli, RenderWithAMeshChoosesItsSpheresToo) {
    const auto dir = temp_dir("max_error_mesh");
    const std::string cessna = std::string(TS_SHARED_DATA) + "/meshes/c172p.ac";
    int spheres[2][2] = {{0, 0}, {0, 0}};
    const char* bounds[2] = {"0.08", "0.06"};
    const char* casters[2] = {"spheres", "triangles"};
    for (int c = 0; c < 2; ++c)
        for (int k = 0; k < 2; ++k) {
            const Result r = run(ts_cmd("render " + quote(kDem) + kCrop + " --mesh " + quote(cessna) +
                                        " --at 5.75,45.2,300agl --scale 30 --sphere-cache-dir " +
                                        quote((dir / "cache").string()) + " --mesh-sun-shadow " + casters[c] +
                                        " --sun-azimuth 135 --sun-elevation 30 --max-error " + bounds[k] + " --out " +
                                        quote((dir / "m.png").string())));
            ASSERT_EQ(r.exit_code, 0) << r.err;
            EXPECT_TRUE(has_choice_line(r.out, bounds[k])) << r.out;
            EXPECT_NE(r.out.find("(its spheres: --max-error chooses how many)"), std::string::npos) << r.out;
            spheres[c][k] = chosen_spheres(r.out);
            EXPECT_GE(spheres[c][k], 8) << r.out;
        }
    EXPECT_LT(spheres[0][0], spheres[0][1]) << "spheres casting the sun: a tighter bound takes more of them";
    EXPECT_EQ(spheres[1][0], 8) << "triangles casting the sun: the fewest spheres";
    EXPECT_EQ(spheres[1][1], 8) << "triangles casting the sun: the fewest spheres";
    const Result both = run(ts_cmd("render " + quote(kDem) + " --mesh " + quote(cessna) +
                                   " --at 5.75,45.2,300agl --spheres 32 --sun-azimuth 135 --sun-elevation 30 "
                                   "--max-error 0.05 --out " + quote((dir / "x.png").string())));
    EXPECT_EQ(both.exit_code, 2) << both.err;
    EXPECT_NE(both.err.find("--max-error chooses --spheres itself"), std::string::npos) << both.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

TEST(MaxErrorCli, RelightChoosesForItsLowestSun) {
    const auto dir = temp_dir("max_error_relight");
    const Result r = run(ts_cmd("relight " + quote(kDem) + kCrop +
                                " --times 2025-06-21T06:00:00Z/2025-06-21T10:00:00Z/PT2H --max-error 0.08 --out " +
                                quote((dir / "frames").string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(has_choice_line(r.out, "0.08")) << r.out;
}

TEST(MaxErrorCli, TilesPrintOneLinePerGroupOfZooms) {
    const auto dir = temp_dir("max_error_tiles");
    const Result r = run(ts_cmd("tiles " + quote(kDem) + kCrop + " --zoom 9-11 --max-error 0.06 --out " +
                                quote((dir / "tiles").string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(has_choice_line(r.out, "0.06")) << r.out;
    EXPECT_NE(r.out.find("zoom"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("sun shadows exact"), std::string::npos) << "tiles shade their sun with the sweep\n" << r.out;
}

TEST(MaxErrorCli, TilesInBlocksChooseEachBlocksDirections) {
    const auto dir = temp_dir("max_error_tile_blocks");
    const Result r = run(ts_cmd("tiles " + quote(kDem) + kCrop + " --zoom 11 --sun-elevation 5 --block-texels 64 "
                                "--block-halo 16 --max-error 0.07 --out " + quote((dir / "tiles").string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("--max-error: level 0 in "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" blocks, directions from each block's roughness: "), std::string::npos) << r.out;
}

TEST(MaxErrorCli, BadBoundsAndConflictingFlagsAreRefusedBeforeAnyWork) {
    const auto dir = temp_dir("max_error_bad");
    const std::string out = " --out " + quote((dir / "x.png").string());
    const std::string sun = " --sun-azimuth 200 --sun-elevation 30";
    struct Case {
        std::string args, message;
    };
    for (const Case& c : {Case{"render " + quote(kDem) + sun + " --max-error 0" + out, "--max-error must be > 0"},
                          Case{"render " + quote(kDem) + sun + " --max-error -1" + out, "--max-error must be > 0"},
                          Case{"render " + quote(kDem) + sun + " --max-error 0.05 --directions 16" + out,
                               "--max-error chooses --directions"},
                          Case{"render " + quote(kDem) + sun + " --max-error 0.05 --sun-shadows exact" + out,
                               "--max-error chooses --sun-shadows"},
                          Case{"relight " + quote(kDem) + " --times 2025-06-21T06:00:00Z/2025-06-21T08:00:00Z/PT1H "
                               "--max-error 0 --out " + quote((dir / "f").string()), "--max-error must be > 0"},
                          Case{"tiles " + quote(kDem) + " --zoom 9 --max-error 0.05 --directions 8 --out " +
                               quote((dir / "t").string()), "--max-error chooses --directions"},
                          Case{"tiles " + quote(kDem) + " --zoom 9 --style hillshade --max-error 0.05 --out " +
                               quote((dir / "t").string()), "relief or color"},
                          Case{"visibility " + quote(kDem) + " --max-error 0.001 --directions 64 --svf " +
                               quote((dir / "svf.tif").string()), "--max-error chooses --directions"},
                          Case{"visibility " + quote(kDem) + " --max-error 0.001 --exact-near-field 4 --svf " +
                               quote((dir / "svf.tif").string()), "--max-error chooses --exact-near-field"}}) {
        const Result r = run(ts_cmd(c.args));
        EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
    EXPECT_FALSE(std::filesystem::exists(dir / "f"));
    EXPECT_FALSE(std::filesystem::exists(dir / "t"));
    EXPECT_FALSE(std::filesystem::exists(dir / "svf.tif"));
}

#ifdef TS_TEST_FLY
TEST(MaxErrorCli, FlyChoosesDirectionsAndTheScreenSpaceBound) {
    const auto dir = temp_dir("max_error_fly");
    const auto path = dir / "path.csv";
    std::ofstream(path) << "t_s,lon,lat,height_m,heading_deg,pitch_deg,roll_deg\n"
                           "0,5.55,45.08,2500,45,-5,0\n"
                           "6,5.62,45.13,2300,50,-8,10\n";
    const Result r = run(ts_cmd("fly " + quote(kDem) + " --frames 1 --size 160x90 --max-error 0.08,4 --path " +
                                quote(path.string()) + " --out " + quote((dir / "frames").string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(has_choice_line(r.out, "0.08")) << r.out;
    EXPECT_NE(r.out.find("screen-space error: --pixel-error 4 px"), std::string::npos) << r.out;
    const Result bad = run(ts_cmd("fly " + quote(kDem) + " --frames 1 --max-error 0.08,4 --pixel-error 1 --out " +
                                  quote((dir / "f2").string())));
    EXPECT_EQ(bad.exit_code, 2) << bad.err;
    EXPECT_NE(bad.err.find("--max-error E,PX sets --pixel-error"), std::string::npos) << bad.err;
}
#endif

}  // namespace
}  // namespace ts::cli_test
