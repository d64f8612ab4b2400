#include "core/fly/bitmap_font.hpp"

namespace ts::fly {
namespace {

constexpr int kFirst = 0x20, kLast = 0x7e;

// Rows as text so the table can be read and corrected by eye.
constexpr const char* kGlyphs[kLast - kFirst + 1][kGlyphRows] = {
#include "core/fly/bitmap_font_glyphs.inc"
};

}  // namespace

bool glyph_pixel(char c, int x, int y) {
    if (x < 0 || x >= kGlyphWidth || y < 0 || y >= kGlyphRows) return false;
    const int code = static_cast<unsigned char>(c);
    const int index = (code < kFirst || code > kLast) ? '?' - kFirst : code - kFirst;
    return kGlyphs[index][y][x] == '#';
}

}  // namespace ts::fly
