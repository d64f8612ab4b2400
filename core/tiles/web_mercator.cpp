#include "core/tiles/web_mercator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ts::tiles {
namespace {
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
}

MercatorBounds tile_bounds(const TileId& t) {
    const double size = 2.0 * kOriginShiftM / double(tiles_per_side(t.z));
    MercatorBounds b;
    b.x0 = -kOriginShiftM + t.x * size;
    b.x1 = -kOriginShiftM + (t.x + 1) * size;
    b.y1 = kOriginShiftM - t.y * size;
    b.y0 = kOriginShiftM - (t.y + 1) * size;
    return b;
}

TileId tile_at(double mx, double my, int z) {
    const std::int64_t n = tiles_per_side(z);
    const double size = 2.0 * kOriginShiftM / double(n);
    auto index = [&](double v) {
        return int(std::clamp<std::int64_t>(std::int64_t(std::floor(v / size)), 0, n - 1));
    };
    return {z, index(mx + kOriginShiftM), index(kOriginShiftM - my)};
}

std::string quadkey(const TileId& t) {
    std::string key;
    key.reserve(std::size_t(t.z));
    for (int i = t.z; i > 0; --i) {
        const int mask = 1 << (i - 1);
        key += char('0' + ((t.x & mask) ? 1 : 0) + ((t.y & mask) ? 2 : 0));
    }
    return key;
}

TileId from_quadkey(const std::string& key) {
    TileId t{int(key.size()), 0, 0};
    for (char c : key) {
        if (c < '0' || c > '3') throw std::invalid_argument("quadkey: digits are 0..3");
        const int d = c - '0';
        t.x = (t.x << 1) | (d & 1);
        t.y = (t.y << 1) | (d >> 1);
    }
    return t;
}

glm::dvec2 lonlat_to_mercator(glm::dvec2 ll) {
    const double lat = std::clamp(ll.y, -kMaxLatitudeDeg, kMaxLatitudeDeg) * kDegToRad;
    return {ll.x * kDegToRad * kEarthRadiusM, kEarthRadiusM * std::log(std::tan(0.25 * 3.14159265358979323846 + 0.5 * lat))};
}

glm::dvec2 mercator_to_lonlat(glm::dvec2 m) {
    return {m.x / kEarthRadiusM / kDegToRad, std::atan(std::sinh(m.y / kEarthRadiusM)) / kDegToRad};
}

int tile_size_shift(int tile_size) {
    for (int s = 0; s < 8; ++s)
        if (tile_size == (256 << s)) return s;
    return -1;
}

}  // namespace ts::tiles
