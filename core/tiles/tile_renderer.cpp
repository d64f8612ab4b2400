#include "core/tiles/tile_renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/raster/srgb.hpp"
#include "core/render/tone_map.hpp"
#include "core/tiles/tile_horn.hpp"

namespace ts::tiles {
namespace {

// Bilinear sample of channel `c` at level texel-centre coordinates, clamped to the raster.
struct Bilinear {
    const ShadeSource& s;
    float operator()(double x, double y, int c) const {
        x = std::clamp(x, 0.0, double(s.width - 1));
        y = std::clamp(y, 0.0, double(s.height - 1));
        const int x0 = std::min(int(x), s.width - 1), x1 = std::min(x0 + 1, s.width - 1);
        const int y0 = std::min(int(y), s.height - 1), y1 = std::min(y0 + 1, s.height - 1);
        const float fx = float(x - x0), fy = float(y - y0);
        const std::size_t ch = std::size_t(s.channels);
        auto at = [&](int col, int row) {
            return s.values[(std::size_t(row) * std::size_t(s.width) + std::size_t(col)) * ch + std::size_t(c)];
        };
        return (at(x0, y0) * (1 - fx) + at(x1, y0) * fx) * (1 - fy) + (at(x0, y1) * (1 - fx) + at(x1, y1) * fx) * fy;
    }
};

// Catmull-Rom (cubic convolution, a = -0.5) sample of channel `c` at level texel-centre
// coordinates, the taps clamped to the raster: interpolating like bilinear, but it keeps the
// slope across a texel, so a level magnified a few times over (a zoom past the DEM's native
// resolution) stays crisp instead of showing the bilinear's creases and blur.
struct CatmullRom {
    const ShadeSource& s;
    static void weights(float t, float (&w)[4]) {
        const float t2 = t * t, t3 = t2 * t;
        w[0] = 0.5f * (-t3 + 2 * t2 - t);
        w[1] = 0.5f * (3 * t3 - 5 * t2 + 2);
        w[2] = 0.5f * (-3 * t3 + 4 * t2 + t);
        w[3] = 0.5f * (t3 - t2);
    }
    float operator()(double x, double y, int c) const {
        x = std::clamp(x, 0.0, double(s.width - 1));
        y = std::clamp(y, 0.0, double(s.height - 1));
        const int x0 = std::min(int(x), s.width - 1), y0 = std::min(int(y), s.height - 1);
        float wx[4], wy[4];
        weights(float(x - x0), wx);
        weights(float(y - y0), wy);
        const std::size_t ch = std::size_t(s.channels);
        float sum = 0;
        for (int j = 0; j < 4; ++j) {
            const int row = std::clamp(y0 - 1 + j, 0, s.height - 1);
            const float* line = s.values.data() + std::size_t(row) * std::size_t(s.width) * ch + std::size_t(c);
            float acc = 0;
            for (int i = 0; i < 4; ++i) acc += wx[i] * line[std::size_t(std::clamp(x0 - 1 + i, 0, s.width - 1)) * ch];
            sum += wy[j] * acc;
        }
        return sum;
    }
};

// Display-linear 0..1 -> sRGB code, tabulated (a pow per pixel would cost more than the PNG).
class SrgbTable {
public:
    SrgbTable() {
        for (int i = 0; i < kSize; ++i)
            code_[std::size_t(i)] = std::uint8_t(std::lround(255.0f * raster::srgb_oetf(float(i) / (kSize - 1))));
    }
    std::uint8_t operator()(float v) const {
        return code_[std::size_t(std::lround(std::clamp(v, 0.0f, 1.0f) * (kSize - 1)))];
    }

private:
    static constexpr int kSize = 1 << 14;
    std::array<std::uint8_t, kSize> code_{};
};

const SrgbTable& srgb_table() {
    static const SrgbTable table;
    return table;
}

// The covered pixels of a visibility style's tile from its source, through `sample`.
template <class Sampler, class LevelX>
void shade_pixels(const Sampler& sample, int channels, bool filmic, const TileScratch& sc, const LevelX& level_x,
                  TileImage& out) {
    if (channels == 1) {
        const SrgbTable& code = srgb_table();
        for (std::size_t k = 0; k < sc.covered.size(); ++k) {
            if (!sc.covered[k]) continue;
            const glm::dvec2 p = sc.at[k];
            const float v = sample(level_x(p.x), level_x(p.y), 0);
            if (std::isnan(v)) continue;  // next to texels outside the terrain: transparent
            out.pixels[2 * k] = code(v);
            out.pixels[2 * k + 1] = 255;
        }
        return;
    }
    const render::Srgb8Encoder& film = render::shared_srgb8_table();
    const SrgbTable& plain = srgb_table();
    for (std::size_t k = 0; k < sc.covered.size(); ++k) {
        if (!sc.covered[k]) continue;
        const glm::dvec2 p = sc.at[k];
        const double x = level_x(p.x), y = level_x(p.y);
        const float rgb[3] = {sample(x, y, 0), sample(x, y, 1), sample(x, y, 2)};
        if (std::isnan(rgb[0] + rgb[1] + rgb[2])) continue;  // next to texels outside the terrain
        std::uint8_t* o = &out.pixels[4 * k];
        if (filmic) {
            const std::array<std::uint8_t, 3> code = film.pixel(glm::vec3(rgb[0], rgb[1], rgb[2]));
            o[0] = code[0], o[1] = code[1], o[2] = code[2];
        } else {
            for (int c = 0; c < 3; ++c) o[c] = plain(rgb[c]);
        }
        o[3] = 255;
    }
}

// CatmullRom's numbers for a one-channel source on a separable pixel map, with each column's
// and row's taps and weights found once (the same operations in the same order).
void shade_grey_cubic_separable(const ShadeSource& source, const TileScratch& sc, double inv_scale, int n, TileImage& out) {
    struct Taps {
        int index[4];
        float weight[4];
    };
    auto taps = [](double v, int size) {
        v = std::clamp(v, 0.0, double(size - 1));
        const int i0 = std::min(int(v), size - 1);
        Taps t;
        CatmullRom::weights(float(v - i0), t.weight);
        for (int k = 0; k < 4; ++k) t.index[k] = std::clamp(i0 - 1 + k, 0, size - 1);
        return t;
    };
    std::vector<Taps> cols(static_cast<std::size_t>(n)), rows(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        cols[std::size_t(i)] = taps(sc.at[std::size_t(i)].x * inv_scale - 0.5, source.width);
        rows[std::size_t(i)] = taps(sc.at[std::size_t(i) * std::size_t(n)].y * inv_scale - 0.5, source.height);
    }
    const SrgbTable& code = srgb_table();
    const std::size_t w = std::size_t(source.width);
    for (int j = 0; j < n; ++j) {
        const Taps& r = rows[std::size_t(j)];
        const float* line[4];
        for (int k = 0; k < 4; ++k) line[k] = source.values.data() + std::size_t(r.index[k]) * w;
        for (int i = 0; i < n; ++i) {
            const std::size_t k = std::size_t(j) * std::size_t(n) + std::size_t(i);
            if (!sc.covered[k]) continue;
            const Taps& c = cols[std::size_t(i)];
            float sum = 0;
            for (int y = 0; y < 4; ++y) {
                float acc = 0;
                for (int x = 0; x < 4; ++x) acc += c.weight[x] * line[y][c.index[x]];
                sum += r.weight[y] * acc;
            }
            if (std::isnan(sum)) continue;  // next to texels outside the terrain: transparent
            out.pixels[2 * k] = code(sum);
            out.pixels[2 * k + 1] = 255;
        }
    }
}

// A lightable tile (lightable_tile.hpp): the window of source texels the covered pixels' Catmull-Rom
// taps reach, and where each pixel samples it (sc.at located, sc.covered set).
std::vector<std::uint8_t> encode_data_tile(const TilePixelMap& map, const ShadeSource& source, const TileFrame& f,
                                           const TileScratch& sc, const LightableEncoding& encoding) {
    const int n = f.size, w = source.width, h = source.height;
    const double inv_scale = 1.0 / double(1 << source.level);
    auto level = [&](double p, int size) { return std::clamp(p * inv_scale - 0.5, 0.0, double(size - 1)); };
    int x_lo = w, x_hi = -1, y_lo = h, y_hi = -1;
    for (std::size_t k = 0; k < sc.covered.size(); ++k) {
        if (!sc.covered[k]) continue;
        const int i = std::min(int(level(sc.at[k].x, w)), w - 1), j = std::min(int(level(sc.at[k].y, h)), h - 1);
        x_lo = std::min(x_lo, i - 1), x_hi = std::max(x_hi, i + 2), y_lo = std::min(y_lo, j - 1), y_hi = std::max(y_hi, j + 2);
    }
    LightablePixels px;
    px.size = n;
    px.covered = sc.covered.data();
    px.separable = map.separable();
    // Between a non-separable map's grid nodes the reader interpolates: a texel more on each side.
    const int margin = px.separable ? 0 : 1;
    LightableTexels tx;
    tx.level_width = w, tx.level_height = h;
    tx.x0 = std::max(0, x_lo - margin), tx.y0 = std::max(0, y_lo - margin);
    tx.width = std::min(w - 1, x_hi + margin) - tx.x0 + 1, tx.height = std::min(h - 1, y_hi + margin) - tx.y0 + 1;
    if (px.separable) {
        for (int i = 0; i < n; ++i) px.x.push_back(float(level(sc.at[std::size_t(i)].x, w) - tx.x0));
        for (int j = 0; j < n; ++j) px.y.push_back(float(level(sc.at[std::size_t(j) * std::size_t(n)].y, h) - tx.y0));
    } else {
        std::vector<glm::dvec2> at;
        map.locate(f, 1, at);  // pixels -1..n: node n is the halo's
        const int m = n + 2;
        for (int j = 0; j <= n; j += px.grid_step)
            for (int i = 0; i <= n; i += px.grid_step) {
                const glm::dvec2 p = at[std::size_t(j + 1) * std::size_t(m) + std::size_t(i + 1)];
                px.x.push_back(float(p.x * inv_scale - 0.5 - tx.x0));
                px.y.push_back(float(p.y * inv_scale - 0.5 - tx.y0));
            }
    }
    const std::size_t ch = std::size_t(source.channels);
    std::vector<float> values(std::size_t(tx.width) * std::size_t(tx.height) * ch);
    for (int r = 0; r < tx.height; ++r)
        std::copy_n(source.values.data() + (std::size_t(tx.y0 + r) * std::size_t(w) + std::size_t(tx.x0)) * ch,
                    std::size_t(tx.width) * ch, values.data() + std::size_t(r) * std::size_t(tx.width) * ch);
    tx.values = values.data();
    return encode_lightable_tile(tx, px, encoding);
}

}  // namespace

void sample_tile_heights(const TilePixelMap& map, const ShadeSource& source, const TileFrame& f, TileScratch& sc,
                         Resampling resampling) {
    const int m = f.size + 2;
    map.locate(f, 1, sc.at);
    const double inv_scale = 1.0 / double(1 << source.level);
    sc.values.resize(std::size_t(m) * m);
    const bool cubic = resampling == Resampling::cubic && source.width >= 2 && source.height >= 2;
    if (map.separable()) {
        // The same samples as below, with the taps of each column and row found once:
        // identical numbers, a fraction of the work.
        struct Taps {
            int i[4];    // cubic: the four taps, clamped; bilinear: i[1], i[2]
            float w[4];  // cubic weights
            float f;     // bilinear weight of i[2]
        };
        auto taps = [](double v, int n) {
            v = std::clamp(v, 0.0, double(n - 1));
            const int i0 = std::min(int(v), n - 1);
            Taps t{};
            t.f = float(v - i0);
            for (int k = 0; k < 4; ++k) t.i[k] = std::clamp(i0 - 1 + k, 0, n - 1);
            CatmullRom::weights(t.f, t.w);
            return t;
        };
        std::vector<Taps> cols(static_cast<std::size_t>(m)), rows(static_cast<std::size_t>(m));
        for (int i = 0; i < m; ++i) {
            cols[std::size_t(i)] = taps(sc.at[std::size_t(i)].x * inv_scale - 0.5, source.width);
            rows[std::size_t(i)] = taps(sc.at[std::size_t(i) * m].y * inv_scale - 0.5, source.height);
        }
        const float* v = source.values.data();
        const std::size_t w = std::size_t(source.width);
        for (int j = 0; j < m; ++j) {
            const Taps& r = rows[std::size_t(j)];
            const float* top = v + std::size_t(r.i[1]) * w;
            const float* bottom = v + std::size_t(r.i[2]) * w;
            float* out = sc.values.data() + std::size_t(j) * m;
            for (int i = 0; i < m; ++i) {
                const Taps& c = cols[std::size_t(i)];
                const float bilinear = (top[c.i[1]] * (1 - c.f) + top[c.i[2]] * c.f) * (1 - r.f) +
                                       (bottom[c.i[1]] * (1 - c.f) + bottom[c.i[2]] * c.f) * r.f;
                float z = bilinear;
                if (cubic) {
                    float sum = 0;
                    for (int b = 0; b < 4; ++b) {
                        const float* line = v + std::size_t(r.i[b]) * w;
                        sum += r.w[b] * (c.w[0] * line[c.i[0]] + c.w[1] * line[c.i[1]] + c.w[2] * line[c.i[2]] +
                                         c.w[3] * line[c.i[3]]);
                    }
                    if (!std::isnan(sum)) z = sum;
                }
                out[i] = z;
            }
        }
        return;
    }
    const Bilinear sample{source};
    const CatmullRom smooth{source};
    for (std::size_t k = 0; k < sc.values.size(); ++k) {
        const glm::dvec2 p = sc.at[k];
        // Off the CRS's domain: any height (the pixel is transparent and its neighbours too).
        if (!std::isfinite(p.x)) {
            sc.values[k] = 0.0f;
            continue;
        }
        const double x = p.x * inv_scale - 0.5, y = p.y * inv_scale - 0.5;
        const float z = cubic ? smooth(x, y, 0) : std::numeric_limits<float>::quiet_NaN();
        sc.values[k] = std::isnan(z) ? sample(x, y, 0) : z;
    }
}

void render_tile(const TilePixelMap& map, const ShadeSource& source, const TileShading& shading, const TileFrame& f,
                 TileScratch& sc, TileImage& out, const LightableEncoding* lightable) {
    const TileStyle& style = *shading.style;
    const bool horn = !style.uses_visibility();
    const int halo = horn ? 1 : 0;
    const int n = f.size, m = n + 2 * halo;
    if (horn)
        sample_tile_heights(map, source, f, sc, shading.resampling);
    else
        map.locate(f, halo, sc.at);
    // Level-0 edge coordinates -> the source level's texel-centre coordinates.
    const double inv_scale = 1.0 / double(1 << source.level);
    auto level_x = [&](double p) { return p * inv_scale - 0.5; };

    sc.covered.assign(std::size_t(n) * n, 0);
    out.covered = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const bool c = map.covered(sc.at[std::size_t(j + halo) * m + std::size_t(i + halo)]);
            sc.covered[std::size_t(j) * n + i] = c;
            out.covered += c;
        }
    out.size = n;
    out.encoded.clear();
    if (style.data_tile()) {
        if (out.covered == 0 || !lightable) return;
        out.encoded = encode_data_tile(map, source, f, sc, *lightable);
        return;
    }
    out.channels = source.channels == 3 ? 4 : 2;
    out.pixels.assign(std::size_t(n) * n * std::size_t(out.channels), 0);
    if (out.covered == 0) return;

    const Bilinear sample{source};
    if (horn) {
        sc.grey.assign(std::size_t(n) * n, 0);
        const HornLight light{shading.sun_azimuth_deg, shading.sun_elevation_deg};
        style.shade_tile(f, sc.values, source.vertical_scale, light, sc.covered.data(), sc.grey.data());
        for (std::size_t k = 0; k < sc.grey.size(); ++k)  // grey 0: no height there (outside the terrain)
            if (sc.covered[k] && sc.grey[k]) out.pixels[2 * k] = sc.grey[k], out.pixels[2 * k + 1] = 255;
        return;
    }
    if (shading.resampling == Resampling::cubic && source.channels == 1 && map.separable()) {
        shade_grey_cubic_separable(source, sc, inv_scale, n, out);
        return;
    }
    if (shading.resampling == Resampling::cubic)
        shade_pixels(CatmullRom{source}, source.channels, source.filmic, sc, level_x, out);
    else
        shade_pixels(sample, source.channels, source.filmic, sc, level_x, out);
}

}  // namespace ts::tiles
