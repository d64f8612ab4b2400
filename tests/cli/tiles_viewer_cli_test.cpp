// The viewer `tiles` writes beside an XYZ tile set (core/tiles/tile_viewer.hpp): tiles.json's
// TileJSON fields, the legend picture of a quantity style, the same description in an MBTiles
// file's metadata, shards merged into the single run's viewer byte for byte, and a folder's
// other files (a user's own index.html) kept. The page itself in a browser:
// docs/tiles/check_viewer.mjs (ctest test_tiles_generated_viewer).
#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sqlite3.h>

#include "tests/cli/cli_support.hpp"
#include "tests/cli/frame_pixels.hpp"

namespace fs = std::filesystem;
using ts::cli_test::kDem;
using ts::cli_test::quote;
using ts::cli_test::run;
using ts::cli_test::temp_dir;
using ts::cli_test::terrashade;

namespace {

const std::string kSmallCrop = " --crop 5.70,45.15,5.80,45.25";
const std::string kInsolation = kSmallCrop + " --style insolation --from 2024-06-20 --to 2024-06-21";

std::string tiles(const std::string& args, const fs::path& out) {
    return quote(terrashade()) + " tiles " + quote(kDem) + " " + args + " --out " + quote(out.string());
}

std::string bytes_of(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

nlohmann::json tilejson(const fs::path& dir) { return nlohmann::json::parse(bytes_of(dir / "tiles.json")); }

std::map<std::string, std::string> mbtiles_metadata(const fs::path& file) {
    std::map<std::string, std::string> meta;
    sqlite3* db = nullptr;
    if (sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) return meta;
    sqlite3_stmt* q = nullptr;
    sqlite3_prepare_v2(db, "SELECT name, value FROM metadata", -1, &q, nullptr);
    while (sqlite3_step(q) == SQLITE_ROW)
        meta[reinterpret_cast<const char*>(sqlite3_column_text(q, 0))] =
            reinterpret_cast<const char*>(sqlite3_column_text(q, 1));
    sqlite3_finalize(q);
    sqlite3_close(db);
    return meta;
}

}  // namespace

TEST(TilesViewer, TileJsonDescribesTheSetAndTheLegendOfItsQuantity) {
    const fs::path d = temp_dir("viewer_insolation");
    const auto r = run(tiles(kInsolation + " --zoom 10", d / "t"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto tj = tilejson(d / "t");
    EXPECT_EQ(tj.at("tilejson"), "3.0.0");
    EXPECT_EQ(tj.at("scheme"), "xyz");
    ASSERT_EQ(tj.at("tiles").size(), 1u);
    EXPECT_EQ(tj.at("tiles")[0], "{z}/{x}/{y}.png");  // relative to tiles.json (the page resolves it)
    EXPECT_EQ(tj.at("minzoom"), 10);
    EXPECT_EQ(tj.at("maxzoom"), 10);
    EXPECT_EQ(tj.at("tile_size"), 256);
    EXPECT_EQ(tj.at("name"), "grenoble_500px insolation");
    // The source the DEM's own metadata names (a Copernicus DEM tile's DTED header), not its file.
    EXPECT_EQ(tj.at("attribution"), "elevation data: Copernicus DEM (TanDEM-X) \u00a9 DLR e.V., Airbus Defence and Space, "
                                    "provided under COPERNICUS by the EU and ESA");
    // The crop's footprint (to half a 0.002-degree texel), the centre inside it at a zoom of the set.
    const auto& b = tj.at("bounds");
    ASSERT_EQ(b.size(), 4u);
    EXPECT_NEAR(b[0].get<double>(), 5.70, 0.003);
    EXPECT_NEAR(b[1].get<double>(), 45.15, 0.003);
    EXPECT_NEAR(b[2].get<double>(), 5.80, 0.003);
    EXPECT_NEAR(b[3].get<double>(), 45.25, 0.003);
    const auto& c = tj.at("center");
    EXPECT_NEAR(c[0].get<double>(), 0.5 * (b[0].get<double>() + b[2].get<double>()), 1e-6);
    EXPECT_NEAR(c[1].get<double>(), 0.5 * (b[1].get<double>() + b[3].get<double>()), 1e-6);
    EXPECT_EQ(c[2], 10);
    // The legend: TileJSON's HTML, naming the picture beside it; the picture the ramp's strip.
    const std::string legend = tj.at("legend");
    EXPECT_NE(legend.find("<img src=\"legend.png\""), std::string::npos) << legend;
    EXPECT_NE(tj.at("description").get<std::string>().find("global irradiation 2024-06-20..2024-06-21 (kWh/m2)"),
              std::string::npos);
    int w = 0, h = 0;
    const auto rgb = ts::cli_test::read_rgb(d / "t" / "legend.png", w, h);
    EXPECT_EQ(w, 320);
    EXPECT_EQ(h, 36);
    // The page: MapLibre pinned with Subresource Integrity, the set's name in its title.
    const std::string page = bytes_of(d / "t" / "index.html");
    EXPECT_NE(page.find("https://unpkg.com/maplibre-gl@5.20.0/dist/maplibre-gl.js\" integrity=\"sha384-"),
              std::string::npos);
    EXPECT_NE(page.find("crossorigin=\"anonymous\""), std::string::npos);
    EXPECT_NE(page.find("<title>grenoble_500px insolation</title>"), std::string::npos);
    EXPECT_NE(page.find("python3 -m http.server"), std::string::npos);
    // Nothing else left beside them (no temporaries).
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(d / "t")) files += e.is_regular_file();
    EXPECT_EQ(files, 4u);  // the job file, tiles.json, index.html, legend.png
}

TEST(TilesViewer, ShadedStylesHaveNoLegendSvfHasItsStretch) {
    const fs::path d = temp_dir("viewer_styles");
    ASSERT_EQ(run(tiles(kSmallCrop + " --zoom 10 --style hillshade --name 'Belledonne <west>' --attribution "
                                     "'Copernicus DEM &copy; DLR/Airbus'",
                        d / "h"))
                  .exit_code,
              0);
    const auto tj = tilejson(d / "h");
    EXPECT_FALSE(tj.contains("legend"));
    EXPECT_FALSE(fs::exists(d / "h" / "legend.png"));
    EXPECT_EQ(tj.at("name"), "Belledonne <west>");
    EXPECT_EQ(tj.at("attribution"), "Copernicus DEM &copy; DLR/Airbus");  // HTML, as the user gave it
    EXPECT_NE(bytes_of(d / "h" / "index.html").find("<title>Belledonne &lt;west&gt;</title>"), std::string::npos);
    ASSERT_EQ(run(tiles(kSmallCrop + " --zoom 10 --style svf --directions 8", d / "s")).exit_code, 0);
    EXPECT_TRUE(tilejson(d / "s").contains("legend"));
    EXPECT_TRUE(fs::exists(d / "s" / "legend.png"));
}

TEST(TilesViewer, ColorTilesHaveTheirPalettesLegend) {
    const fs::path d = temp_dir("viewer_color");
    ASSERT_EQ(run(tiles(kSmallCrop + " --zoom 10 --style color --directions 8 --snow-line 2000", d / "c")).exit_code, 0);
    const auto tj = tilejson(d / "c");
    ASSERT_TRUE(tj.contains("legend"));
    EXPECT_NE(tj.at("description").get<std::string>().find("land colour by height (hypsometric), snow above 2000 m (m)"),
              std::string::npos)
        << tj.at("description");
    // The strip's bar shows the palette: its low end the first stop's tint (sRGB 175 206 162),
    // its high end the last's (199 197 193).
    int w = 0, h = 0;
    const auto rgb = ts::cli_test::read_rgb(d / "c" / "legend.png", w, h);
    ASSERT_GT(w, 100);
    auto colour_in_bar = [&](double at) {
        int best = 0;
        std::array<int, 3> found{};
        for (int y = 0; y < h; ++y) {
            const std::size_t i = (std::size_t(y) * std::size_t(w) + std::size_t(at * (w - 1))) * 3;
            const int g = rgb[i + 1];
            if (g > best && rgb[i] != rgb[i + 1]) best = g, found = {rgb[i], rgb[i + 1], rgb[i + 2]};
        }
        return found;
    };
    const auto low = colour_in_bar(0.03), high = colour_in_bar(0.97);
    EXPECT_NEAR(low[1], 206, 6);
    EXPECT_GT(low[1], low[0]);   // green lowlands
    EXPECT_GT(high[0], high[2]);  // warm grey summits
}

TEST(TilesViewer, MbtilesMetadataSaysWhatTileJsonSays) {
    const fs::path d = temp_dir("viewer_mbtiles");
    ASSERT_EQ(run(tiles(kInsolation + " --zoom 10", d / "t.mbtiles")).exit_code, 0);
    ASSERT_EQ(run(tiles(kInsolation + " --zoom 10", d / "xyz")).exit_code, 0);
    EXPECT_FALSE(fs::exists(d / "index.html"));  // an MBTiles file gets no page
    auto meta = mbtiles_metadata(d / "t.mbtiles");
    const auto tj = tilejson(d / "xyz");
    for (const char* key : {"name", "description", "attribution"}) EXPECT_EQ(meta[key], tj.at(key)) << key;
    EXPECT_EQ(meta["minzoom"], "10");
    EXPECT_EQ(meta["maxzoom"], "10");
    double w = 0, s = 0, e = 0, n = 0;
    ASSERT_EQ(std::sscanf(meta["bounds"].c_str(), "%lf,%lf,%lf,%lf", &w, &s, &e, &n), 4);
    EXPECT_NEAR(w, tj.at("bounds")[0].get<double>(), 1e-7);
    EXPECT_NEAR(n, tj.at("bounds")[3].get<double>(), 1e-7);
}

TEST(TilesViewer, ShardsMergeIntoTheSingleRunsViewer) {
    const fs::path d = temp_dir("viewer_shards");
    const std::string args = kInsolation + " --zoom 10-12";
    ASSERT_EQ(run(tiles(args, d / "single")).exit_code, 0);
    for (int k : {0, 1, 2})
        ASSERT_EQ(run(tiles(args + " --shard " + std::to_string(k) + "/3", d / ("s" + std::to_string(k)))).exit_code, 0);
    const auto r = run(quote(terrashade()) + " merge " + quote((d / "s0").string()) + " " + quote((d / "s1").string()) +
                       " " + quote((d / "s2").string()) + " --out " + quote((d / "all").string()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* file : {"tiles.json", "index.html", "legend.png"}) {
        ASSERT_TRUE(fs::exists(d / "all" / file)) << file;
        EXPECT_EQ(bytes_of(d / "all" / file), bytes_of(d / "single" / file)) << file;
    }
    // A shard whose viewer differs (another name) is not a shard of this job.
    ASSERT_EQ(run(tiles(args + " --shard 1/3 --name other", d / "s1other")).exit_code, 0);
    const auto bad = run(quote(terrashade()) + " merge " + quote((d / "s0").string()) + " " +
                         quote((d / "s1other").string()) + " " + quote((d / "s2").string()) + " --out " +
                         quote((d / "bad").string()));
    EXPECT_EQ(bad.exit_code, 2) << bad.out;
    EXPECT_FALSE(fs::exists(d / "bad"));
}

TEST(TilesViewer, ResumeAndOverwriteKeepTheViewerTrueAndAUsersPageSafe) {
    const fs::path d = temp_dir("viewer_overwrite");
    ASSERT_EQ(run(tiles(kInsolation + " --zoom 10", d / "t")).exit_code, 0);
    const std::string page = bytes_of(d / "t" / "index.html"), tj = bytes_of(d / "t" / "tiles.json");
    ASSERT_EQ(run(tiles(kInsolation + " --zoom 10 --resume", d / "t")).exit_code, 0);
    EXPECT_EQ(bytes_of(d / "t" / "index.html"), page);
    EXPECT_EQ(bytes_of(d / "t" / "tiles.json"), tj);
    // Another job over it: the old legend goes with the old tiles.
    ASSERT_EQ(run(tiles(kSmallCrop + " --zoom 10 --style hillshade --overwrite", d / "t")).exit_code, 0);
    EXPECT_FALSE(fs::exists(d / "t" / "legend.png"));
    EXPECT_FALSE(tilejson(d / "t").contains("legend"));
    // A folder of the user's with an index.html of its own: refused before any work, untouched.
    fs::create_directories(d / "site");
    std::ofstream(d / "site" / "index.html") << "my page";
    const auto r = run(tiles(kSmallCrop + " --zoom 10 --style hillshade --overwrite", d / "site"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("index.html"), std::string::npos) << r.err;
    EXPECT_EQ(bytes_of(d / "site" / "index.html"), "my page");
    EXPECT_FALSE(fs::exists(d / "site" / "10"));
}

// A DEM that does not say who made it (the shared ETOPO1 GeoTIFF) is credited by its file
// name, with a note that says how to credit its source; --attribution silences the note.
const std::string kUncreditedDem = ts::cli_test::kSharedDems + "etopo1_global_1deg.tif";

TEST(TilesViewer, AnUncreditedDemIsCreditedByItsNameWithANote) {
    const fs::path d = temp_dir("viewer_uncredited");
    const std::string base = quote(terrashade()) + " tiles " + quote(kUncreditedDem) + " --zoom 0 --style hillshade";
    const auto r = run(base + " --out " + quote((d / "named").string()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("does not say who made it"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--attribution"), std::string::npos) << r.err;
    EXPECT_EQ(tilejson(d / "named").at("attribution"), "elevation data: etopo1_global_1deg.tif");
    const auto given = run(base + " --attribution 'ETOPO1: NOAA NCEI' --out " + quote((d / "given").string()));
    ASSERT_EQ(given.exit_code, 0) << given.err;
    EXPECT_EQ(given.err.find("does not say who made it"), std::string::npos) << given.err;
    EXPECT_EQ(tilejson(d / "given").at("attribution"), "ETOPO1: NOAA NCEI");
}
