// `terrashade spheres` end to end: the JSON it writes (spheres, count, coverage, excess,
// seconds, cached), the preview PNG, the cache on the second run, and one-line exit-2 errors
// for bad input before any heavy work.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_support.hpp"

namespace {
namespace fs = std::filesystem;
using ts::cli_test::quote;
using ts::cli_test::Result;
using ts::cli_test::run_ts;

const std::string kTruck = std::string(TS_SHARED_DATA) + "/meshes/CesiumMilkTruck/CesiumMilkTruck.gltf";

nlohmann::json read_json(const fs::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in);
}

void expect_one_line_error(const Result& r) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

TEST(SpheresCli, WritesJsonPreviewAndUsesTheCache) {
    const fs::path dir = ts::cli_test::temp_dir("spheres");
    const fs::path out = dir / "truck.json", png = dir / "truck.png", cache = dir / "cache";
    const std::string args = "spheres " + quote(kTruck) + " --count 32 --out " + quote(out.string()) + " --preview " +
                             quote(png.string()) + " --cache-dir " + quote(cache.string());
    const Result r = run_ts(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = read_json(out);
    EXPECT_EQ(j.at("count").get<int>(), int(j.at("spheres").size()));
    EXPECT_GE(j.at("count").get<int>(), 28);
    EXPECT_GE(j.at("surface_coverage").get<double>(), 0.995);
    EXPECT_GE(j.at("excess_volume_ratio").get<double>(), 0.0);
    EXPECT_GT(j.at("seconds").get<double>(), 0.0);
    EXPECT_FALSE(j.at("cached").get<bool>());
    for (const auto& s : j.at("spheres")) {
        EXPECT_EQ(s.at("center").size(), 3u);
        EXPECT_GT(s.at("radius").get<double>(), 0.0);
        EXPECT_LT(s.at("radius").get<double>(), 6.0);  // metres: the truck is ~5 m long
    }
    ASSERT_TRUE(fs::exists(png));
    EXPECT_GT(fs::file_size(png), 1000u);

    const Result again = run_ts(args);
    ASSERT_EQ(again.exit_code, 0) << again.err;
    const auto k = read_json(out);
    EXPECT_TRUE(k.at("cached").get<bool>());
    EXPECT_EQ(k.at("spheres"), j.at("spheres"));
    // No temporary names left beside the outputs.
    for (const auto& e : fs::directory_iterator(dir))
        EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

TEST(SpheresCli, BadInputIsOneLineAndExit2) {
    const fs::path dir = ts::cli_test::temp_dir("spheres_bad");
    const std::string out = " --out " + quote((dir / "s.json").string()) + " --no-cache";
    expect_one_line_error(run_ts("spheres " + quote(kTruck) + " --count 7" + out));
    expect_one_line_error(run_ts("spheres " + quote(kTruck) + " --count 513" + out));
    expect_one_line_error(run_ts("spheres " + quote(kTruck) + " --count many" + out));
    const Result missing = run_ts("spheres " + quote((dir / "nope.gltf").string()) + out);
    expect_one_line_error(missing);
    EXPECT_NE(missing.err.find("nope.gltf"), std::string::npos) << missing.err;
    std::ofstream(dir / "empty.obj").flush();
    expect_one_line_error(run_ts("spheres " + quote((dir / "empty.obj").string()) + out));
    std::ofstream(dir / "junk.ac") << "not an AC3D file\n";
    expect_one_line_error(run_ts("spheres " + quote((dir / "junk.ac").string()) + out));
    expect_one_line_error(run_ts("spheres " + quote(kTruck) + " --out " + quote((dir / "s.txt").string())));
    expect_one_line_error(run_ts("spheres " + quote(kTruck) + " --out " + quote((dir / "no_dir" / "s.json").string())));
    expect_one_line_error(run_ts("spheres " + quote(kTruck) + out + " --preview " + quote((dir / "p.jpg").string())));
    EXPECT_FALSE(fs::exists(dir / "s.json"));
}

}  // namespace
