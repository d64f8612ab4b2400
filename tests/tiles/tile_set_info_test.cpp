// A tile set's description as TileJSON and on its page: any name or attribution a user gives
// stays valid JSON and inert text in the page (core/tiles/tile_set_info.hpp, tile_viewer.hpp).
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/tiles/tile_set_info.hpp"
#include "core/tiles/tile_viewer.hpp"

namespace {

ts::tiles::TileSetInfo awkward_info() {
    ts::tiles::TileSetInfo info;
    info.name = "Alps \"north\" </script><b>\\ \x01 tab\tend";
    info.description = "@NAME@ & more";
    info.attribution = "<a href=\"https://example.org\">DEM</a> © someone";
    info.bounds = {5.0, 45.0, 6.0, 46.0};
    info.minzoom = 7, info.maxzoom = 10;
    info.legend_file = "legend.png", info.legend_alt = "a \"quoted\" ramp";
    return info;
}

}  // namespace

TEST(TileSetInfo, TileJsonParsesBackToWhatWasGiven) {
    const auto info = awkward_info();
    const auto j = nlohmann::json::parse(ts::tiles::tilejson_text(info));
    EXPECT_EQ(j.at("name"), info.name);
    EXPECT_EQ(j.at("attribution"), info.attribution);
    EXPECT_EQ(j.at("minzoom"), 7);
    EXPECT_EQ(j.at("center")[2], 8);
    EXPECT_DOUBLE_EQ(j.at("center")[0].get<double>(), 5.5);
    EXPECT_EQ(j.at("legend"), "<img src=\"legend.png\" alt=\"a &quot;quoted&quot; ramp\">");
    const auto m = ts::tiles::mbtiles_metadata(info);
    EXPECT_EQ(m.at("bounds"), "5.0000000,45.0000000,6.0000000,46.0000000");
    EXPECT_EQ(m.at("center"), "5.5000000,45.5000000,8");
}

TEST(TileSetInfo, ThePageShowsTheNameAsTextAndPinsMaplibre) {
    const std::string page = ts::tiles::viewer_page_html(awkward_info());
    EXPECT_EQ(page.find("</script><b>"), std::string::npos);
    EXPECT_NE(page.find("Alps &quot;north&quot; &lt;/script&gt;&lt;b&gt;"), std::string::npos);
    EXPECT_NE(page.find("@NAME@ &amp; more"), std::string::npos);  // a description is not expanded
    EXPECT_NE(page.find(std::string("src=\"") + ts::tiles::kMaplibreJsUrl + "\" integrity=\"" +
                        ts::tiles::kMaplibreJsSri + "\" crossorigin=\"anonymous\""),
              std::string::npos);
    EXPECT_NE(std::string(ts::tiles::kMaplibreJsUrl).find(std::string("@") + ts::tiles::kMaplibreVersion + "/"),
              std::string::npos);
    EXPECT_EQ(page.find('@' + std::string("JS_")), std::string::npos);  // every key filled
}
