// Stability through the command line: a DEM that is all void is refused with one line and
// exit 2 by every command that computes (before any work, nothing written); DEMs of 1x1 and
// 2x2 cells are computed (finite svf, a picture). The camera under the terrain is refused by
// render (tests/cli/messages_cli_test.cpp, "below the terrain"). And `bench report --tiny`:
// the report CSV's shape (columns, knobs, one default per knob), not its timings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "core/dem/read_dem.hpp"
#include "tests/cli/cli_support.hpp"

namespace ts::cli_test {
namespace {

namespace fs = std::filesystem;
const std::string kDem = std::string(TS_SOURCE_DIR) + "/data/grenoble_500px.tif";
const std::string kShared = std::string(TS_SHARED_DATA);

std::string ts_cmd(const std::string& args) { return quote(terrashade()) + " " + args; }

fs::path make_window(const fs::path& dir, const std::string& name, const std::string& src, const std::string& win) {
    const fs::path out = dir / name;
    const Result r = run("gdal_translate -q -srcwin " + win + " " + quote(src) + " " + quote(out.string()));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return out;
}

TEST(StabilityCli, AnAllVoidDemExitsTwoWithOneLineAndWritesNothing) {
    const fs::path dir = temp_dir("all_void");
    // nodata_3x3.tif: its lower-right 2x2 block is nodata.
    const fs::path dem = make_window(dir, "void.tif", kShared + "/dem/nodata_3x3.tif", "1 1 2 2");
    const std::string d = quote(dem.string());
    for (const std::string& args :
         {"visibility " + d + " --svf " + quote((dir / "svf.tif").string()),
          "render " + d + " --sun-azimuth 135 --sun-elevation 30 --out " + quote((dir / "r.png").string()),
          "relight " + d + " --times 2025-06-21T10:00:00Z/2025-06-21T11:00:00Z/PT1H --out " +
              quote((dir / "frames").string()),
          "tiles " + d + " --zoom 10 --out " + quote((dir / "tiles").string())}) {
        const Result r = run(ts_cmd(args));
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
        EXPECT_NE(r.err.find("no valid height anywhere"), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    for (const char* out : {"svf.tif", "r.png", "frames", "tiles"}) EXPECT_FALSE(fs::exists(dir / out)) << out;
}

TEST(StabilityCli, OneByOneAndTwoByTwoDemsGiveFiniteSvfAndAPicture) {
    const fs::path dir = temp_dir("tiny_dems");
    for (const std::string win : {"1 1", "2 2"}) {
        const std::string tag = win.substr(0, 1);
        const fs::path dem = make_window(dir, "dem" + tag + ".tif", kDem, "100 100 " + win);
        const fs::path svf = dir / ("svf" + tag + ".tif"), png = dir / ("r" + tag + ".png");
        const Result v = run(ts_cmd("visibility " + quote(dem.string()) + " --svf " + quote(svf.string())));
        ASSERT_EQ(v.exit_code, 0) << v.err;
        const dem::Dem s = dem::read_dem(svf);
        for (float x : s.z) {
            EXPECT_TRUE(std::isfinite(x)) << win;
            EXPECT_GT(x, 0.0f) << win;
            EXPECT_LE(x, 1.0f) << win;
        }
        if (tag == "1") {
            EXPECT_EQ(s.z.at(0), 1.0f) << "nothing can block a single cell";
        }
        const Result r = run(ts_cmd("render " + quote(dem.string()) + " --sun-azimuth 135 --sun-elevation 30 --out " +
                                    quote(png.string())));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        EXPECT_TRUE(fs::exists(png)) << win;
    }
}

TEST(BenchReportCli, TinyReportWritesOneCsvWithTheDocumentedColumnsAndOneDefaultPerKnob) {
    const fs::path dir = temp_dir("report");
    const Result r = run(ts_cmd("bench report --tiny --only 'visibility knobs,render,sun,sphere' --data " +
                                quote(kShared) + " --out " + quote((dir / "out").string())));
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("expected about"), std::string::npos) << r.out;
    std::ifstream in(dir / "out" / "report.csv");
    std::string header;
    ASSERT_TRUE(std::getline(in, header));
    EXPECT_EQ(header, "command,knob,value,is_default,seconds,error,error_metric,dem");
    std::map<std::string, int> defaults;  // knob -> rows marked default
    std::set<std::string> knobs;
    std::string line;
    int rows = 0;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream ss(line);
        for (std::string cell; std::getline(ss, cell, ',');) f.push_back(cell);
        if (line.back() == ',') f.push_back("");
        ASSERT_EQ(f.size(), 8u) << line;
        ++rows;
        const std::string key = f[0] + "/" + f[1] + "/" + f[7];
        knobs.insert(f[0] + "/" + f[1]);
        defaults[key] += f[3] == "1";
        EXPECT_FALSE(f[5].empty()) << "every row has an error: " << line;
        EXPECT_GE(std::stod(f[5]), 0.0) << line;
    }
    EXPECT_GT(rows, 10);
    for (const char* k : {"visibility/directions", "visibility/horizon_method", "visibility/exact_near_field",
                          "visibility/pyramid_schedule", "render/directions", "render/sun_shadows",
                          "render/sun_near_field", "render/sphere_count"})
        EXPECT_TRUE(knobs.count(k)) << k;
    for (const auto& [key, n] : defaults) {
        // tiny measures neither D = 32 for render nor 64 spheres: those two have no default row.
        if (key.rfind("render/directions", 0) != 0 && key.rfind("render/sphere_count", 0) != 0) {
            EXPECT_EQ(n, 1) << key << ": one default per knob";
        }
    }
}

}  // namespace
}  // namespace ts::cli_test
