#include "app/insolation_quicklook.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "core/fly/bitmap_font.hpp"
#include "core/raster/raster_writer.hpp"

namespace ts::app {
namespace {

// A perceptually ordered ramp for energy: dark blue, purple, red, orange, pale yellow
// (the stops of matplotlib's "inferno", a public colour map, sampled at 0, .25, .5, .75, 1).
constexpr float kRamp[5][3] = {{0, 0, 4}, {87, 16, 110}, {188, 55, 84}, {249, 142, 9}, {252, 255, 164}};

void ramp(float x, std::uint8_t* rgb) {
    x = std::clamp(x, 0.0f, 1.0f) * 4.0f;
    const int i = std::min(3, int(x));
    const float f = x - float(i);
    for (int c = 0; c < 3; ++c) rgb[c] = std::uint8_t(std::lround(kRamp[i][c] + f * (kRamp[i + 1][c] - kRamp[i][c])));
}

void text(std::vector<std::uint8_t>& img, int width, int height, int x0, int y0, const std::string& s) {
    for (std::size_t k = 0; k < s.size(); ++k)
        for (int y = 0; y < fly::kGlyphRows; ++y)
            for (int x = 0; x < fly::kGlyphWidth; ++x) {
                const int px = x0 + int(k) * fly::kGlyphAdvance + x, py = y0 + y;
                if (px < 0 || py < 0 || px >= width || py >= height || !fly::glyph_pixel(s[k], x, y)) continue;
                std::uint8_t* p = &img[(std::size_t(py) * width + px) * 3];
                p[0] = p[1] = p[2] = 255;
            }
}

std::string number(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, std::abs(v) >= 100 ? "%.0f" : "%.3g", double(v));
    return buf;
}

}  // namespace

QuicklookRange write_insolation_quicklook(const std::string& path, int width, int height, const float* values,
                                          const std::string& title, const std::string& unit) {
    const std::size_t n = std::size_t(width) * height;
    std::vector<float> valid;
    valid.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
        if (std::isfinite(values[i])) valid.push_back(values[i]);
    QuicklookRange range;
    if (!valid.empty()) {
        auto at = [&](double q) {
            const auto k = std::size_t(q * double(valid.size() - 1));
            std::nth_element(valid.begin(), valid.begin() + std::ptrdiff_t(k), valid.end());
            return valid[k];
        };
        range.lo = at(0.01), range.hi = at(0.99);
    }
    if (!(range.hi > range.lo)) range.hi = range.lo + 1e-3f;
    // The legend: a title line, the ramp bar, the values under its ends and middle.
    const int legend = 4 + fly::kLineAdvance + 10 + 2 + fly::kLineAdvance;
    const int out_w = std::max(width, 160), out_h = height + legend;
    std::vector<std::uint8_t> img(std::size_t(out_w) * out_h * 3, 0);
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c) {
            const float v = values[std::size_t(r) * width + c];
            if (std::isfinite(v)) ramp((v - range.lo) / (range.hi - range.lo), &img[(std::size_t(r) * out_w + c) * 3]);
        }
    int y = height + 4;
    text(img, out_w, out_h, 4, y, title);
    y += fly::kLineAdvance;
    const int bar0 = 4, bar1 = out_w - 5;
    for (int x = bar0; x <= bar1; ++x) {
        std::uint8_t rgb[3];
        ramp(float(x - bar0) / float(bar1 - bar0), rgb);
        for (int yy = y; yy < y + 10; ++yy) std::copy(rgb, rgb + 3, &img[(std::size_t(yy) * out_w + x) * 3]);
    }
    y += 12;
    const std::string lo = "<=" + number(range.lo), hi = ">=" + number(range.hi) + " " + unit;
    const std::string mid = number(0.5f * (range.lo + range.hi));
    text(img, out_w, out_h, bar0, y, lo);
    text(img, out_w, out_h, (bar0 + bar1) / 2 - int(mid.size()) * fly::kGlyphAdvance / 2, y, mid);
    text(img, out_w, out_h, bar1 + 1 - int(hi.size()) * fly::kGlyphAdvance, y, hi);
    raster::write_u8_image(path, out_w, out_h, 3, img.data(), nullptr);
    return range;
}

}  // namespace ts::app
