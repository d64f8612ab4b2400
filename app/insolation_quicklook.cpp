#include "app/insolation_quicklook.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "app/quicklook_legend.hpp"
#include "core/raster/raster_writer.hpp"

namespace ts::app {

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
    // The legend in a margin under the map (app/quicklook_legend.hpp).
    const Legend legend{title, unit, range.lo, range.hi, inferno_ramp};
    const int out_w = std::max(width, 160), out_h = height + legend_height();
    std::vector<std::uint8_t> img(std::size_t(out_w) * out_h * 3, 0);
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c) {
            const float v = values[std::size_t(r) * width + c];
            if (std::isfinite(v))
                inferno_ramp((v - range.lo) / (range.hi - range.lo), &img[(std::size_t(r) * out_w + c) * 3]);
        }
    draw_legend(img, out_w, out_h, height, legend);
    raster::write_u8_image(path, out_w, out_h, 3, img.data(), nullptr);
    return range;
}

}  // namespace ts::app
