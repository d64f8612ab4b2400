// `terrashade insolation` end to end on a crop of the Grenoble DSM: the Cloud-Optimized
// GeoTIFF's bands, their descriptions and units (gdalinfo and GDAL's COG validator as the
// oracles), the quick-look, and one-line exit-2 refusals before any work that leave no file
// behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_support.hpp"

namespace {

using ts::cli_test::quote;
using ts::cli_test::Result;
using ts::cli_test::run_ts;

const std::string kCroppedDem = quote(ts::cli_test::kDem) + " --crop 5.70,45.15,5.80,45.25";

TEST(InsolationCli, TwoDaysGiveTenDescribedBandsAndAQuicklook) {
    const auto dir = ts::cli_test::temp_dir("insolation_ok");
    const std::string tif = (dir / "i.tif").string(), png = (dir / "i.png").string();
    const Result r = run_ts("insolation " + kCroppedDem + " --from 2024-06-20 --to 2024-06-21 --by day --out " + quote(tif) +
                         " --quicklook " + quote(png));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("wrote " + tif + " (10 bands"), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(png));
    const Result g = ts::cli_test::run("gdalinfo -json -stats " + quote(tif));
    ASSERT_EQ(g.exit_code, 0) << "gdalinfo (gdal-bin, installed by scripts/test.sh): " << g.err;
    const auto j = nlohmann::json::parse(g.out);
    const auto& bands = j.at("bands");
    ASSERT_EQ(bands.size(), 10u);
    EXPECT_EQ(bands[0].at("description").get<std::string>(), "global irradiation 2024-06-20 (kWh/m2)");
    EXPECT_EQ(bands[9].at("description").get<std::string>(), "hours of direct sun 2024-06-21 (h)");
    EXPECT_EQ(bands[0].at("unit").get<std::string>(), "kWh/m2");
    EXPECT_EQ(bands[9].at("unit").get<std::string>(), "h");
    EXPECT_EQ(bands[0].at("noDataValue"), "NaN");
    // A Cloud-Optimized GeoTIFF of band-separate planes that GDAL's validator takes without a
    // warning (the line on the headers' size is printed only then).
    EXPECT_EQ(j["metadata"]["IMAGE_STRUCTURE"]["LAYOUT"], "COG");
    EXPECT_EQ(j["metadata"]["IMAGE_STRUCTURE"]["INTERLEAVE"], "BAND");
    const Result valid = ts::cli_test::run(
        "/usr/bin/python3 -m osgeo_utils.samples.validate_cloud_optimized_geotiff --full-check=yes " + quote(tif));
    EXPECT_EQ(valid.exit_code, 0) << valid.out << valid.err;
    EXPECT_NE(valid.out.find("The size of all IFD headers is"), std::string::npos) << valid.out << valid.err;
    // Around the solstice at 45 N a clear day gives ~8-9 kWh/m2 on open ground and ~15.5 h of
    // sun; no texel can get more than the extraterrestrial ~12 kWh/m2 on a sun-facing plane.
    const double max_global = bands[0].at("maximum").get<double>();
    EXPECT_GT(max_global, 7.0);
    EXPECT_LT(max_global, 12.5);
    EXPECT_LE(bands[4].at("maximum").get<double>(), 16.0);
}

TEST(InsolationCli, BadInputIsOneLineExitTwoAndNoOutput) {
    const auto dir = ts::cli_test::temp_dir("insolation_bad");
    const std::string tif = (dir / "bad.tif").string();
    for (const std::string args :
         {"--year 2024 --linke-monthly 1,2,3", "--from 2024-05-02 --to 2024-05-01", "--from 2023-02-29 --to 2023-03-01",
          "--year 2024 --from 2024-01-01 --to 2024-01-02", "--year 2024 --albedo -0.5", "--year 2024 --linke 0",
          "--year 2024 --clear-sky-index 0", "--year 2024 --step 0", "--from 2024-01-01", "--year 9000",
          "--year 2024 --materials /nonexistent/cover.tif"}) {
        const Result r = run_ts("insolation " + kCroppedDem + " " + args + " --out " + quote(tif));
        EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(tif)) << args;
    }
}

// --materials: each WorldCover class's shortwave albedo replaces --albedo. Snow and ice (70)
// everywhere must give what --albedo 0.6 gives, texel for texel (the means of every band).
TEST(InsolationCli, LandCoverGivesEachTexelItsShortwaveAlbedo) {
    const auto dir = ts::cli_test::temp_dir("insolation_materials");
    const std::string cover = (dir / "worldcover_snow.tif").string();
    const Result made = ts::cli_test::run("gdal_create -of GTiff -outsize 60 60 -bands 1 -ot Byte -burn 70 -a_srs EPSG:4326 "
                                          "-a_ullr 5.69 45.26 5.81 45.14 " + quote(cover));
    ASSERT_EQ(made.exit_code, 0) << made.err;
    auto stats = [&](const std::string& name, const std::string& args) {
        const std::string tif = (dir / name).string();
        const Result r = run_ts("insolation " + kCroppedDem + " --from 2024-06-01 --to 2024-06-30 " + args + " --out " + quote(tif));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        const Result g = ts::cli_test::run("gdalinfo -json -stats " + quote(tif));
        return nlohmann::json::parse(g.out).at("bands");
    };
    const auto snow = stats("snow.tif", "--albedo 0.2 --materials " + quote(cover));
    const auto same = stats("same.tif", "--albedo 0.6");
    const auto grass = stats("grass.tif", "--albedo 0.2");
    for (int b = 0; b < 5; ++b)
        EXPECT_NEAR(snow[b].at("mean").get<double>(), same[b].at("mean").get<double>(),
                    1e-4 * std::abs(same[b].at("mean").get<double>()) + 2e-3) << "band " << b;  // gdalinfo's 3 decimals
    // Three times grass's 0.2, and a little more: brighter terrain also lights itself more (the
    // first pass's ground, standing for the higher bounces, reflects 0.6 too).
    const double ratio = snow[3].at("mean").get<double>() / grass[3].at("mean").get<double>();
    EXPECT_GT(ratio, 3.0);
    EXPECT_LT(ratio, 3.1);
}

// A DEM of the sea floor (ETOPO1 over the Pacific, -971 to -5548 m) is summed as the sea's surface:
// the same map as the same grid at 0 m. Taken as it was, 4 km of water counted as 4 km of extra
// air in the ESRA air mass, 15% too little sun.
TEST(InsolationCli, TheSeaFloorIsSummedAsTheSeasSurface) {
    const auto dir = ts::cli_test::temp_dir("insolation_sea");
    const std::string floor = (dir / "floor.tif").string(), flat = (dir / "flat.tif").string();
    ASSERT_EQ(ts::cli_test::run("gdal_translate -q -srcwin 30 80 8 8 " + quote(ts::cli_test::kSharedDems + "etopo1_global_1deg.tif") +
                                " " + quote(floor)).exit_code, 0);
    ASSERT_EQ(ts::cli_test::run("gdal_calc.py --quiet -A " + quote(floor) + " --outfile=" + quote(flat) + " --calc=A*0").exit_code, 0);
    auto global = [&](const std::string& dem, const std::string& name) {
        const std::string tif = (dir / name).string();
        const Result r = run_ts("insolation " + quote(dem) + " --from 2024-06-01 --to 2024-06-02 --out " + quote(tif));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        const Result g = ts::cli_test::run("gdalinfo -json -stats " + quote(tif));
        return std::make_pair(nlohmann::json::parse(g.out).at("bands").at(0).at("mean").get<double>(), r.err);
    };
    const auto [sea, note] = global(floor, "sea.tif");
    const auto [surface, none] = global(flat, "surface.tif");
    EXPECT_NEAR(sea, surface, 1e-4 * surface);
    EXPECT_NE(note.find("holds the sea floor"), std::string::npos) << note;
    EXPECT_EQ(none.find("sea floor"), std::string::npos) << none;
}

}  // namespace

namespace {

std::string bytes_of(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Shards sum rows of the map with one run's horizons (each shard's receivers swept over the
// whole DEM), so the merge is the single run's file byte for byte; what is not one whole job
// is refused with one line and no output.
TEST(InsolationCli, ShardsMergeIntoTheSingleRunsFileByteForByte) {
    const auto dir = ts::cli_test::temp_dir("insolation_shards");
    const std::string job = "insolation " + kCroppedDem + " --from 2024-03-01 --to 2024-04-30 --by month --step 10";
    const Result whole = run_ts(job + " --out " + quote((dir / "whole.tif").string()));
    ASSERT_EQ(whole.exit_code, 0) << whole.err;
    std::string parts;
    for (int k = 0; k < 3; ++k) {
        const std::string part = (dir / ("p" + std::to_string(k) + ".tif")).string();
        const Result r = run_ts(job + " --shard " + std::to_string(k) + "/3 --out " + quote(part));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_NE(r.out.find("shard " + std::to_string(k) + "/3: rows"), std::string::npos) << r.out;
        parts = quote(part) + " " + parts;  // given in any order
    }
    const std::string merged = (dir / "merged.tif").string();
    const Result m = run_ts("merge " + parts + " --out " + quote(merged));
    ASSERT_EQ(m.exit_code, 0) << m.err;
    EXPECT_EQ(bytes_of(merged), bytes_of(dir / "whole.tif"));

    // The reflection's gather reads rows beyond a shard's, which its first pass covers: with a
    // short radius each shard sums only part of the DEM's rows, and still merges into the single
    // run's file; the gather's settings make another job.
    const std::string short_job = job + " --reflection-directions 8 --reflection-radius 4";
    ASSERT_EQ(run_ts(short_job + " --out " + quote((dir / "short.tif").string())).exit_code, 0);
    std::string short_parts;
    for (int k = 0; k < 3; ++k) {
        const std::string part = (dir / ("s" + std::to_string(k) + ".tif")).string();
        ASSERT_EQ(run_ts(short_job + " --shard " + std::to_string(k) + "/3 --out " + quote(part)).exit_code, 0);
        short_parts += " " + quote(part);
    }
    const std::string short_merged = (dir / "short_merged.tif").string();
    ASSERT_EQ(run_ts("merge" + short_parts + " --out " + quote(short_merged)).exit_code, 0);
    EXPECT_EQ(bytes_of(short_merged), bytes_of(dir / "short.tif"));
    EXPECT_NE(bytes_of(short_merged), bytes_of(dir / "whole.tif"));
    const Result mixed = run_ts("merge " + quote((dir / "p0.tif").string()) + " " + quote((dir / "p1.tif").string()) +
                                " " + quote((dir / "s2.tif").string()) + " --out " + quote((dir / "mixed.tif").string()));
    EXPECT_EQ(mixed.exit_code, 2) << mixed.err;

    // Another job's shard (another albedo), a shard missing, a map that is no shard, --quicklook.
    const std::string other = (dir / "other.tif").string();
    ASSERT_EQ(run_ts(job + " --albedo 0.5 --shard 2/3 --out " + quote(other)).exit_code, 0);
    const std::string p0 = quote((dir / "p0.tif").string()), p1 = quote((dir / "p1.tif").string());
    const std::string bad = (dir / "bad.tif").string();
    for (const std::string& args : {"merge " + p0 + " " + p1 + " " + quote(other), "merge " + p0 + " " + p1,
                                   "merge " + p0 + " " + p1 + " " + quote((dir / "whole.tif").string())}) {
        const Result r = run_ts(args + " --out " + quote(bad));
        EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(bad)) << args;
    }
    const Result q = run_ts(job + " --shard 0/3 --out " + quote(bad) + " --quicklook " +
                            quote((dir / "bad.png").string()));
    EXPECT_EQ(q.exit_code, 2) << q.err;
    EXPECT_FALSE(std::filesystem::exists(bad));
}

}  // namespace
