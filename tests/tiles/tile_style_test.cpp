// The tile styles' registry: each style is registered once under its own name, what each says
// about itself is what the tile pipeline relied on when styles were an enum, --style's names
// and its error come from the registry, and a Horn style shades a tile as tile_horn.hpp does.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/tiles/tile_horn.hpp"
#include "core/tiles/tile_pixels.hpp"
#include "core/tiles/tile_style.hpp"
#include "core/util/error.hpp"

namespace ts::tiles {
namespace {

TEST(TileStyle, EveryStyleIsRegisteredOnceInUserOrder) {
    std::vector<std::string> names;
    std::set<const TileStyle*> distinct;
    for (const TileStyle* s : tile_styles()) names.emplace_back(s->name()), distinct.insert(s);
    EXPECT_EQ(names, (std::vector<std::string>{"relief", "hillshade", "multidirectional", "svf", "color", "insolation", "lightable"}));
    EXPECT_EQ(distinct.size(), names.size());
    for (const std::string& n : names) EXPECT_EQ(find_tile_style(n)->name(), n);
    EXPECT_EQ(find_tile_style("Relief"), nullptr);
    EXPECT_EQ(&default_tile_style(), find_tile_style("relief"));
    EXPECT_EQ(TileShading{}.style, find_tile_style("relief"));
    EXPECT_EQ(tile_style_names(" | "), "relief | hillshade | multidirectional | svf | color | insolation | lightable");
}

TEST(TileStyle, ParseNamesEveryStyleInItsError) {
    EXPECT_EQ(&parse_tile_style("svf"), find_tile_style("svf"));
    try {
        parse_tile_style("slope");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("use relief, hillshade, multidirectional, svf, color, insolation or lightable"), std::string::npos) << e.what();
    }
}

TEST(TileStyle, EachStyleSaysWhatTheEnumSwitchesDid) {
    struct Want {
        const char* name;
        bool visibility;
        int channels;
        bool true_heights, flat, halo, max_error, contrast, colours = false, latitudes = false, filmic = false;
    };
    for (const Want& w : {Want{"relief", true, 1, false, true, true, true, true},
                          Want{"hillshade", false, 1, false, false, true, false, false},
                          Want{"multidirectional", false, 1, false, false, true, false, false},
                          Want{"svf", true, 1, false, false, false, false, false},
                          Want{"color", true, 3, true, true, true, true, false, true, false, true},
                          Want{"insolation", true, 3, false, false, true, false, false, false, true, false}}) {
        const TileStyle& s = *find_tile_style(w.name);
        SCOPED_TRACE(w.name);
        EXPECT_EQ(s.uses_visibility(), w.visibility);
        EXPECT_EQ(s.channels(), w.channels);
        EXPECT_EQ(s.needs_true_heights(), w.true_heights);
        EXPECT_EQ(s.colours_land(), w.colours);
        EXPECT_EQ(s.relative_to_flat(), w.flat);
        EXPECT_EQ(s.halo_without_far_field(), w.halo);
        EXPECT_EQ(s.takes_max_error(), w.max_error);
        EXPECT_EQ(s.takes_relief_contrast(), w.contrast);
        EXPECT_EQ(s.needs_latitudes(), w.latitudes);
        EXPECT_EQ(s.filmic(), w.filmic);
    }
}

TEST(TileStyle, HornStylesShadeATileAsTileHorn) {
    const TileFrame f = tile_frame({9, 266, 181}, 256);
    const int m = f.size + 2;
    std::vector<float> heights(std::size_t(m) * m);
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) heights[std::size_t(j) * m + i] = float(300.0 * std::sin(0.05 * i) * std::cos(0.07 * j));
    const std::vector<std::uint8_t> covered(std::size_t(f.size) * f.size, 1);
    const HornLight light{300.0, 40.0};
    std::vector<std::uint8_t> want(covered.size()), got(covered.size());
    horn_hillshade(f, heights, 1.5, light, covered.data(), want.data());
    find_tile_style("hillshade")->shade_tile(f, heights, 1.5, light, covered.data(), got.data());
    EXPECT_EQ(got, want);
    horn_multidirectional(f, heights, 1.5, light, covered.data(), want.data());
    find_tile_style("multidirectional")->shade_tile(f, heights, 1.5, light, covered.data(), got.data());
    EXPECT_EQ(got, want);
    EXPECT_THROW(find_tile_style("svf")->shade_tile(f, heights, 1.5, light, covered.data(), got.data()), std::logic_error);
}

}  // namespace
}  // namespace ts::tiles
