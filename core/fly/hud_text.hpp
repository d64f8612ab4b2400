#pragma once
// The HUD as a small RGBA8 image: lines of text in the bitmap font on a dark translucent box,
// so it reads over bright snow and dark valleys alike. The GPU only blends it over the frame.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace ts::fly {

struct HudStyle {
    int scale = 1;                 // every font pixel becomes scale x scale image pixels
    int padding = 3;               // font pixels between the box's edge and the text
    std::uint8_t text = 240;       // grey level of the text (opaque)
    std::uint8_t box = 0;          // grey level of the backing box
    std::uint8_t box_alpha = 150;  // its opacity, 0..255
};

// Straight (not premultiplied) alpha, rows top down, width * height * 4 bytes.
struct HudImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
};

// The box just holds the longest line; no lines (or only empty ones) give a 0x0 image.
HudImage rasterise_hud(std::span<const std::string> lines, const HudStyle& style);

// The font scale for a frame this wide: 2 above 1200 px, so the text stays legible on large
// windows, else 1.
int hud_scale_for_width(int frame_width);

}  // namespace ts::fly
