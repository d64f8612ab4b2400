#include "core/fly/hud_text.hpp"

#include <algorithm>

#include "core/fly/bitmap_font.hpp"

namespace ts::fly {

HudImage rasterise_hud(std::span<const std::string> lines, const HudStyle& style) {
    std::size_t columns = 0;
    for (const std::string& l : lines) columns = std::max(columns, l.size());
    HudImage img;
    if (columns == 0) return img;
    const int s = std::max(1, style.scale);
    const int pad = std::max(0, style.padding);
    // The last line needs only its glyph rows, not a whole line advance.
    const int text_w = int(columns) * kGlyphAdvance - 1;
    const int text_h = int(lines.size() - 1) * kLineAdvance + kGlyphRows;
    img.width = (text_w + 2 * pad) * s;
    img.height = (text_h + 2 * pad) * s;
    img.rgba.resize(std::size_t(img.width) * std::size_t(img.height) * 4);
    for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
        img.rgba[i] = img.rgba[i + 1] = img.rgba[i + 2] = style.box;
        img.rgba[i + 3] = style.box_alpha;
    }
    for (std::size_t li = 0; li < lines.size(); ++li)
        for (std::size_t ci = 0; ci < lines[li].size(); ++ci)
            for (int gy = 0; gy < kGlyphRows; ++gy)
                for (int gx = 0; gx < kGlyphWidth; ++gx) {
                    if (!glyph_pixel(lines[li][ci], gx, gy)) continue;
                    const int x0 = (pad + int(ci) * kGlyphAdvance + gx) * s;
                    const int y0 = (pad + int(li) * kLineAdvance + gy) * s;
                    for (int y = y0; y < y0 + s; ++y)
                        for (int x = x0; x < x0 + s; ++x) {
                            std::uint8_t* p = &img.rgba[(std::size_t(y) * std::size_t(img.width) + std::size_t(x)) * 4];
                            p[0] = p[1] = p[2] = style.text;
                            p[3] = 255;
                        }
                }
    return img;
}

int hud_scale_for_width(int frame_width) { return frame_width > 1200 ? 2 : 1; }

}  // namespace ts::fly
