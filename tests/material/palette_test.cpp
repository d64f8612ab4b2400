// The palettes (core/material/palette.hpp): gdaldem color-relief's text format, fitting percent
// stops, interpolation, the built-in palettes' design, and the materials they give.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/material/palette_materials.hpp"
#include "core/raster/srgb.hpp"
#include "core/util/error.hpp"

namespace ts::render {
namespace {

double luminance(const glm::vec3& linear) { return 0.2126 * linear.x + 0.7152 * linear.y + 0.0722 * linear.z; }

glm::vec3 linear_of(const glm::vec3& srgb) {
    return {raster::srgb_eotf(srgb.x / 255.0f), raster::srgb_eotf(srgb.y / 255.0f), raster::srgb_eotf(srgb.z / 255.0f)};
}

TEST(Palette, ReadsGdaldemColorReliefText) {
    const Palette p = Palette::parse("# a comment\n\n2000 255 255 255\n0,0,128,0\n1000\t200 100 50 255\nnv 0 0 0 0\n",
                                     "ramp.txt");
    ASSERT_EQ(p.stops().size(), 3u);  // sorted by height, nv read and left out
    EXPECT_EQ(p.stops()[0].value, 0);
    EXPECT_EQ(p.stops()[2].value, 2000);
    EXPECT_EQ(p.srgb_at(1000), glm::vec3(200, 100, 50));
    EXPECT_EQ(p.srgb_at(500), glm::vec3(100, 114, 25));  // linear in sRGB between stops, as gdaldem
    EXPECT_EQ(p.srgb_at(-100), glm::vec3(0, 128, 0));     // held beyond the first and last stops
    EXPECT_EQ(p.srgb_at(9000), glm::vec3(255, 255, 255));
}

TEST(Palette, PercentStopsAreFittedToTheHeightRange) {
    const Palette p = Palette::parse("0% 0 0 0\n50% 100 100 100\n100% 200 200 200\n", "p");
    EXPECT_TRUE(p.has_percent_stops());
    const Palette f = p.fitted(1000, 3000);
    EXPECT_FALSE(f.has_percent_stops());
    EXPECT_EQ(f.stops()[1].value, 2000);
    EXPECT_EQ(f.srgb_at(1500), glm::vec3(50, 50, 50));
    // A flat DEM: one colour, no division by zero.
    EXPECT_EQ(p.fitted(5, 5).srgb_at(5), glm::vec3(0, 0, 0));
}

TEST(Palette, NamesTheFileAndLineOfABadEntry) {
    const auto message = [](const std::string& text) {
        try {
            Palette::parse(text, "my.txt");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message("0 0 0 0\n100 red\n"), "my.txt: line 2: give HEIGHT R G B [A] (HEIGHT in metres, N% or nv; R G B in 0..255)");
    EXPECT_EQ(message("0 0 0 300\n"),
              "my.txt: line 1: '300' is not a colour component (R G B are numbers in 0..255; colour names are not read)");
    EXPECT_EQ(message("abc 0 0 0\n"), "my.txt: line 1: 'abc' is not a height (metres, N% or nv)");
    EXPECT_EQ(message("150% 0 0 0\n"), "my.txt: line 1: '150%': a percentage of the height range must be within 0..100");
    EXPECT_EQ(message("# nothing\n"), "my.txt: no colour stop (gdaldem color-relief text: HEIGHT R G B per line)");
    EXPECT_EQ(message(std::string("\x89PNG\r\n\x1a\n", 8)),
              "my.txt: not a colour table (gdaldem color-relief text: HEIGHT R G B per line)");
}

TEST(Palette, TheDefaultCarriesReliefNotLuminance) {
    // Relief first: the default's tints are of one luminance (within 2%), so light and shadow
    // alone change the brightness.
    const Palette p = *Palette::named(kDefaultPalette);
    double lo = 1e9, hi = 0;
    for (const PaletteStop& s : p.stops()) {
        const double y = luminance(linear_of(s.srgb));
        lo = std::min(lo, y), hi = std::max(hi, y);
        // Never the white-blue of snow: blue below red at every stop.
        EXPECT_LT(s.srgb.z, s.srgb.x) << s.value;
    }
    EXPECT_LT(hi / lo, 1.02);
    // Its albedos are those of land (0.1..0.3), not of snow (0.8).
    const Palette f = p.fitted(0, 4000);
    for (double h : {0.0, 1000.0, 2000.0, 3000.0, 4000.0}) {
        const double y = luminance(f.albedo_at(h));
        EXPECT_GT(y, 0.10) << h;
        EXPECT_LT(y, 0.30) << h;
    }
    // grey: one colour, albedo 0.18.
    const Palette grey = Palette::named("grey")->fitted(0, 4000);
    EXPECT_NEAR(luminance(grey.albedo_at(0)), 0.18, 0.005);
    EXPECT_EQ(grey.albedo_at(0), grey.albedo_at(4000));
    EXPECT_FALSE(Palette::named("rainbow"));
}

struct Grid {
    std::vector<float> z;
    std::vector<std::uint8_t> voids;
    terrain::HeightGrid grid;
    NormalField normals;
    Grid(int w, int h, float low, float high) : z(std::size_t(w * h)), voids(std::size_t(w * h), 0) {
        // Flat rows, each higher than the one above it by (high - low) / (h - 1).
        for (int r = 0; r < h; ++r)
            for (int c = 0; c < w; ++c) z[std::size_t(r * w + c)] = low + (high - low) * float(r) / float(h - 1);
        grid = terrain::HeightGrid::uniform(w, h, z, 1e6, 1e6);  // spacing so wide the rows are flat
        normals = terrain_normals(grid);
    }
};

TEST(PaletteMaterials, NoSnowUnlessASnowLineIsGiven) {
    Grid g(3, 9, 200, 4800);
    ColorDesign d;
    d = fit_colors(d, 200, 4800);
    const MaterialRaster plain = palette_materials(g.grid, g.normals, d);
    for (std::size_t i = 0; i < plain.size(); ++i) {
        EXPECT_NE(plain.surface[i], Surface::snow_ice);
        EXPECT_LT(plain.albedo_r[i], 0.35f);
    }
    d.snow_line_m = 3000;
    const MaterialRaster winter = palette_materials(g.grid, g.normals, d);
    const std::size_t top = g.grid.index(1, 8), bottom = g.grid.index(1, 0);
    EXPECT_EQ(winter.surface[top], Surface::snow_ice);
    EXPECT_NEAR(winter.albedo_b[top], surface_params(Surface::snow_ice).albedo.z, 1e-5);
    EXPECT_EQ(winter.albedo_r[bottom], plain.albedo_r[bottom]);
}

TEST(PaletteMaterials, WaterFromVoidsAndTheFlatSeaLandCoverFromData) {
    Grid g(3, 3, -5, 100);
    g.voids[g.grid.index(2, 2)] = 1;
    g.grid.void_mask = g.voids;
    std::vector<std::uint8_t> cover(9, 0);
    cover[g.grid.index(0, 1)] = 10;  // tree cover where the data says so
    const ColorDesign d = fit_colors(ColorDesign{}, -5, 100);
    const MaterialRaster m = palette_materials(g.grid, g.normals, d, cover);
    EXPECT_EQ(m.water[g.grid.index(0, 0)], 1);  // flat, below sea level
    EXPECT_EQ(m.water[g.grid.index(2, 2)], 1);  // a void
    EXPECT_EQ(m.surface[g.grid.index(0, 1)], Surface::tree_cover);
    EXPECT_EQ(m.water[g.grid.index(1, 1)], 0);
    EXPECT_EQ(m.surface[g.grid.index(1, 1)], Surface::bare);  // the palette's land
}

TEST(PaletteMaterials, PercentStopsFollowTheWholeDemNotAWindow) {
    // Two windows of one DEM coloured with the DEM's fit agree on a shared height.
    const ColorDesign d = fit_colors(ColorDesign{}, 0, 3000);
    Grid a(2, 2, 1000, 1500), b(2, 2, 1500, 2900);
    const MaterialRaster ma = palette_materials(a.grid, a.normals, d), mb = palette_materials(b.grid, b.normals, d);
    EXPECT_EQ(ma.albedo_g[a.grid.index(0, 1)], mb.albedo_g[b.grid.index(0, 0)]);
}

TEST(PaletteMaterials, ADemWithTheSeaFloorGetsSeaTintsAndNoSeaSurface) {
    // ETOPO-like: 6000 m below to 3000 m above sea level.
    const ColorDesign d = fit_colors(ColorDesign{}, -6000, 3000);
    EXPECT_TRUE(d.sea_floor);
    const Palette& p = d.palette;
    const glm::vec3 shore = p.srgb_at(-1), deep = p.srgb_at(-6000), land = p.srgb_at(0), low_land = p.srgb_at(10);
    EXPECT_GT(shore.z, shore.x + 30);  // blue below sea level
    EXPECT_GT(deep.z, deep.x + 60);
    EXPECT_LT(luminance(linear_of(deep)), luminance(linear_of(shore)));  // darker with depth
    EXPECT_EQ(land, glm::vec3(175, 206, 162));  // the land's first tint at 0 m, not the sea's
    EXPECT_GT(low_land.y, low_land.z);          // green lowlands
    EXPECT_NEAR(p.srgb_at(3000).x, 199, 0.5);   // the land tints span [0, highest]
    // A second fit keeps the first (a window of the DEM does not refit it).
    EXPECT_EQ(fit_colors(d, -10, 10).palette.describe(), p.describe());
    // The sea floor is terrain: no texel below sea level is water unless it is a void.
    Grid g(3, 3, -3000, -100);
    g.voids[g.grid.index(2, 2)] = 1;
    g.grid.void_mask = g.voids;
    const MaterialRaster m = palette_materials(g.grid, g.normals, d);
    EXPECT_EQ(m.water[g.grid.index(0, 0)], 0);
    EXPECT_EQ(m.water[g.grid.index(1, 1)], 0);
    EXPECT_EQ(m.water[g.grid.index(2, 2)], 1);
    // A DEM whose lowest land is a depression (the Dead Sea's shore) is not one with a sea floor.
    EXPECT_FALSE(fit_colors(ColorDesign{}, -430, 1000).sea_floor);
    // A user's percent stops keep gdaldem's meaning: of the whole range.
    ColorDesign user;
    user.palette = Palette::parse("0% 0 0 0\n100% 255 255 255\n", "user.txt");
    const ColorDesign fitted = fit_colors(user, -6000, 3000);
    EXPECT_TRUE(fitted.sea_floor);
    EXPECT_NEAR(fitted.palette.srgb_at(-1500).x, 127.5, 0.5);
}

}  // namespace
}  // namespace ts::render
