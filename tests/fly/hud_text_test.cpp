// The HUD overlay's rasteriser: every printable character has a glyph, a known string's lit
// pixels have the expected bounding box, the box is dark and translucent and scales by 2.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/fly/bitmap_font.hpp"
#include "core/fly/hud_status.hpp"
#include "core/fly/hud_text.hpp"

namespace ts::fly {
namespace {

int lit_pixels(char c) {
    int n = 0;
    for (int y = 0; y < kGlyphRows; ++y)
        for (int x = 0; x < kGlyphWidth; ++x) n += glyph_pixel(c, x, y) ? 1 : 0;
    return n;
}

TEST(HudText, EveryPrintableCharacterButSpaceHasAGlyph) {
    EXPECT_EQ(lit_pixels(' '), 0);
    for (char c = '!'; c <= '~'; ++c) EXPECT_GT(lit_pixels(c), 0) << "'" << c << "'";
    // Distinct glyphs for characters a HUD confuses easily.
    const auto same = [](char a, char b) {
        for (int y = 0; y < kGlyphRows; ++y)
            for (int x = 0; x < kGlyphWidth; ++x)
                if (glyph_pixel(a, x, y) != glyph_pixel(b, x, y)) return false;
        return true;
    };
    EXPECT_FALSE(same('0', 'O'));
    EXPECT_FALSE(same('1', 'l'));
    EXPECT_FALSE(same('5', 'S'));
    // Outside printable ASCII: '?'; outside the cell: nothing.
    EXPECT_TRUE(same('\n', '?'));
    EXPECT_FALSE(glyph_pixel('#', -1, 0));
    EXPECT_FALSE(glyph_pixel('#', kGlyphWidth, 0));
    // Only descenders use the last row.
    for (char c = '!'; c <= '~'; ++c) {
        bool bottom = false;
        for (int x = 0; x < kGlyphWidth; ++x) bottom |= glyph_pixel(c, x, kGlyphRows - 1);
        const bool descender = std::string("gjpqy,;").find(c) != std::string::npos;
        EXPECT_EQ(bottom, descender) << "'" << c << "'";
    }
}

struct Box {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};

Box text_box(const HudImage& img) {
    Box b;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            if (img.rgba[(std::size_t(y) * std::size_t(img.width) + std::size_t(x)) * 4 + 3] == 255) {
                b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y);
                b.x1 = std::max(b.x1, x), b.y1 = std::max(b.y1, y);
            }
    return b;
}

TEST(HudText, AKnownStringHasItsBoundingBox) {
    // "HUD" has no descender: 3 glyphs of 5 columns, 1 apart, 7 rows, after the padding.
    const std::vector<std::string> lines = {"HUD"};
    HudStyle style;
    style.padding = 3;
    const HudImage img = rasterise_hud(lines, style);
    EXPECT_EQ(img.width, 3 * kGlyphAdvance - 1 + 2 * 3);
    EXPECT_EQ(img.height, kGlyphRows + 2 * 3);
    const Box b = text_box(img);
    EXPECT_EQ(b.x0, 3);
    EXPECT_EQ(b.y0, 3);
    EXPECT_EQ(b.x1, 3 + 2 * kGlyphAdvance + kGlyphWidth - 1);
    EXPECT_EQ(b.y1, 3 + 6);
    // A second line with a descender moves the bottom one line and one row down.
    const std::vector<std::string> two = {"HUD", "gy"};
    const Box b2 = text_box(rasterise_hud(two, style));
    EXPECT_EQ(b2.y1, 3 + kLineAdvance + kGlyphRows - 1);
    EXPECT_EQ(b2.x1, b.x1);
}

TEST(HudText, TheBackingBoxIsDarkAndTranslucentAndTheTextOpaque) {
    const std::vector<std::string> lines = {"45 fps", "sun 35 deg"};
    HudStyle style;
    const HudImage img = rasterise_hud(lines, style);
    ASSERT_EQ(img.rgba.size(), std::size_t(img.width) * std::size_t(img.height) * 4);
    std::size_t text = 0, box = 0;
    for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
        if (img.rgba[i + 3] == 255) {
            ++text;
            EXPECT_EQ(img.rgba[i], style.text);
        } else {
            ++box;
            EXPECT_EQ(img.rgba[i + 3], style.box_alpha);
            EXPECT_EQ(img.rgba[i], style.box);
        }
    }
    EXPECT_GT(text, 50u);
    EXPECT_GT(box, 4 * text);  // mostly box: the text is thin
    EXPECT_GT(style.box_alpha, 100);  // dark enough under near-white text over snow
    EXPECT_LT(style.box_alpha, 255);  // and the terrain shows through
    // The corner is box.
    EXPECT_EQ(img.rgba[3], style.box_alpha);
}

TEST(HudText, ScaleTwoDoublesEverything) {
    const std::vector<std::string> lines = {"N45.1 E5.7"};
    HudStyle one, two;
    two.scale = 2;
    const HudImage a = rasterise_hud(lines, one), b = rasterise_hud(lines, two);
    ASSERT_EQ(b.width, 2 * a.width);
    ASSERT_EQ(b.height, 2 * a.height);
    for (int y = 0; y < b.height; ++y)
        for (int x = 0; x < b.width; ++x)
            ASSERT_EQ(b.rgba[(std::size_t(y) * std::size_t(b.width) + std::size_t(x)) * 4 + 3],
                      a.rgba[(std::size_t(y / 2) * std::size_t(a.width) + std::size_t(x / 2)) * 4 + 3]);
    EXPECT_EQ(hud_scale_for_width(960), 1);
    EXPECT_EQ(hud_scale_for_width(1920), 2);
}

TEST(HudText, NoTextNoImage) {
    const std::vector<std::string> none;
    EXPECT_EQ(rasterise_hud(none, HudStyle{}).width, 0);
    const std::vector<std::string> empty = {"", ""};
    EXPECT_TRUE(rasterise_hud(empty, HudStyle{}).rgba.empty());
}

TEST(HudText, TheStatusLinesAreTheTitlesContent) {
    HudStatus s;
    s.lead = "45 fps";
    s.frame_ms = 22.14, s.select_ms = 0.05, s.draw_ms = 21.0;
    s.patches = 812, s.triangles = 210345, s.error_px = 2.0;
    s.lon_deg = 5.7234, s.lat_deg = 45.1234, s.height_m = 2310, s.heading_deg = 45;
    s.solar_time = "16:52", s.sun_elevation_deg = 35, s.camera = "chase", s.recording = true;
    const std::vector<std::string> lines = hud_lines(s);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[0], "45 fps  22.1 ms (select 0.05, draw 21.0)  err<=2.00 px");
    EXPECT_EQ(lines[1], "812 patches  210345 tris  chase  REC");
    EXPECT_EQ(lines[2], "45.1234N 5.7234E 2310 m  hdg 045  16:52 solar  sun 35 deg");
    for (const std::string& l : lines) EXPECT_LE(l.size(), 64u);
    EXPECT_EQ(hud_title(s), "terrashade fly | " + lines[0] + " | " + lines[1] + " | " + lines[2]);
    // A streamed DEM adds its resident tiles, with a + while some load.
    s.tiles = 14, s.pending_tiles = 3;
    EXPECT_EQ(hud_lines(s)[1], "812 patches  210345 tris  tiles 14+  chase  REC");
    s.pending_tiles = 0;
    EXPECT_EQ(hud_lines(s)[1], "812 patches  210345 tris  tiles 14  chase  REC");
    EXPECT_LE(hud_lines(s)[1].size(), 64u);
}

}  // namespace
}  // namespace ts::fly
