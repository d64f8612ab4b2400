#include "app/quicklook_legend.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/fly/bitmap_font.hpp"
#include "core/raster/raster_writer.hpp"

namespace ts::app {
namespace {

void text(std::vector<std::uint8_t>& img, int width, int height, int x0, int y0, const std::string& s) {
    for (std::size_t k = 0; k < s.size(); ++k)
        for (int y = 0; y < fly::kGlyphRows; ++y)
            for (int x = 0; x < fly::kGlyphWidth; ++x) {
                const int px = x0 + int(k) * fly::kGlyphAdvance + x, py = y0 + y;
                if (px < 0 || py < 0 || px >= width || py >= height || !fly::glyph_pixel(s[k], x, y)) continue;
                std::uint8_t* p = &img[(std::size_t(py) * std::size_t(width) + std::size_t(px)) * 3];
                p[0] = p[1] = p[2] = 255;
            }
}

std::string number(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, std::abs(v) >= 100 ? "%.0f" : "%.3g", double(v));
    return buf;
}

}  // namespace

int legend_height() { return 4 + fly::kLineAdvance + 10 + 2 + fly::kLineAdvance; }

void draw_legend(std::vector<std::uint8_t>& img, int width, int height, int y0, const Legend& legend) {
    int y = y0 + 4;
    text(img, width, height, 4, y, legend.title);
    y += fly::kLineAdvance;
    const int bar0 = 4, bar1 = width - 5;
    for (int x = bar0; x <= bar1; ++x) {
        std::uint8_t rgb[3];
        legend.ramp(float(x - bar0) / float(bar1 - bar0), rgb);
        for (int yy = y; yy < y + 10 && yy < height; ++yy)
            std::copy(rgb, rgb + 3, &img[(std::size_t(yy) * std::size_t(width) + std::size_t(x)) * 3]);
    }
    y += 12;
    const std::string lo = "<=" + number(legend.lo);
    const std::string hi = ">=" + number(legend.hi) + (legend.unit.empty() ? "" : " " + legend.unit);
    const std::string mid = number(0.5f * (legend.lo + legend.hi));
    text(img, width, height, bar0, y, lo);
    text(img, width, height, (bar0 + bar1) / 2 - int(mid.size()) * fly::kGlyphAdvance / 2, y, mid);
    text(img, width, height, bar1 + 1 - int(hi.size()) * fly::kGlyphAdvance, y, hi);
}

void write_legend_png(const std::string& path, int width, const Legend& legend) {
    width = std::max(width, 200);
    const int height = legend_height();
    std::vector<std::uint8_t> img(std::size_t(width) * std::size_t(height) * 3, 0);
    draw_legend(img, width, height, 0, legend);
    raster::write_u8_image(path, width, height, 3, img.data(), nullptr);
}

std::string legend_path_for(const std::string& picture) {
    const std::filesystem::path p(picture);
    return (p.parent_path() / (p.stem().string() + "_legend" + p.extension().string())).string();
}

}  // namespace ts::app
