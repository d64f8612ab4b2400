#pragma once
// The HUD's font: a fixed-width 5x7 bitmap of printable ASCII (0x20..0x7e) with a one-row
// descender, drawn on the CPU so the overlay needs no font file nor a text library.
namespace ts::fly {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphRows = 8;     // 7 body rows, then the descender row
inline constexpr int kGlyphAdvance = 6;  // one empty column between characters
inline constexpr int kLineAdvance = 10;  // two empty rows between lines

// Whether pixel (x, y) of character c is lit; x in [0, kGlyphWidth), y in [0, kGlyphRows) from
// the top. Characters outside printable ASCII are drawn as '?'.
bool glyph_pixel(char c, int x, int y);

}  // namespace ts::fly
