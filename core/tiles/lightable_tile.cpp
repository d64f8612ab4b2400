#include "core/tiles/lightable_tile.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>

#include "core/raster/png_writer.hpp"

namespace ts::tiles {
namespace {

constexpr double kObliquityDeg = 23.44;
// Horizons below this always let the sun through (the lowest sun that lights anything).
constexpr double kLowestHorizonRad = -5.0 * std::numbers::pi / 180.0;
// Around the sun's band in a direction: its disc's radius and the sun sampling's step.
constexpr double kBandMarginRad = 0.5 * std::numbers::pi / 180.0;

using Matrix9 = std::array<std::array<double, kLightTransfer>, kLightTransfer>;

// Eigenvectors (columns of v) and eigenvalues (diagonal of a) of a symmetric matrix by cyclic
// Jacobi rotations: 9 x 9 once per tile.
void jacobi_eigen(Matrix9& a, Matrix9& v) {
    constexpr int n = kLightTransfer;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) v[i][j] = i == j;
    for (int sweep = 0; sweep < 50; ++sweep) {
        double off = 0;
        for (int p = 0; p < n; ++p)
            for (int q = p + 1; q < n; ++q) off += a[p][q] * a[p][q];
        if (off < 1e-30) return;
        for (int p = 0; p < n; ++p)
            for (int q = p + 1; q < n; ++q) {
                if (std::abs(a[p][q]) < 1e-300) continue;
                const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
                const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
                const double c = 1 / std::sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < n; ++k) {
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq, a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < n; ++k) {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk, a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < n; ++k) {
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq, v[k][q] = s * vkp + c * vkq;
                }
            }
    }
}

std::uint8_t quantise(double v, double lo, double hi, int levels = 255) {
    const double t = hi > lo ? (v - lo) / (hi - lo) : 0.0;
    return std::uint8_t(std::lround(std::clamp(t, 0.0, 1.0) * levels));
}

// The horizons' codes: 0..kHorizonLevels over each plane's range (7 bits). On the Grenoble crop
// against 255 levels: zooms 8-13 13% smaller, agreement with relief unchanged at zooms 9-11
// (p99 3/1/2/1 codes, mean +0.005); 95 levels 18% smaller with p99 still 3/1/2/1 at zoom 10 but
// the noon maximum 10 -> 22 codes; 63 levels p99 4 at 05:30 (beyond the test's 3).
constexpr int kHorizonLevels = 127;

// Horizon planes are stored as differences from their prediction by the previous stored plane
// except every kHorizonKeyInterval-th one and one whose direction does not follow the
// previous plane's: a reader decodes a plane from at most this many. On the Grenoble crop's
// zooms 8-13 (93 planes, 8-bit codes), a chain through all planes made the tiles 7.7% smaller than no
// prediction, 32 5.4%, 8 ~1%; decoding a plane costs the reader one table look-up per texel
// per plane of its chain (16 zoom-9 tiles' last plane: ~80 ms in Node at 32, ~440 ms unbounded).
constexpr int kHorizonKeyInterval = 32;

bool predicted_plane(const std::vector<SunBand>& bands, std::size_t j) {
    return j % std::size_t(kHorizonKeyInterval) != 0 && bands[j].direction == bands[j - 1].direction + 1;
}

// The code of plane (lo, hi) nearest each code of the previous plane (prev_lo, prev_hi): the
// ranges as the header stores them (float32), in double, with no multiply feeding an add (no
// fused multiply-add may change a rounding), so the reader's JavaScript gets the same codes.
std::array<std::uint8_t, 256> predicted_horizon_codes(double prev_lo, double prev_hi, double lo, double hi, int levels) {
    const double pl = double(float(prev_lo)), pr = double(float(prev_hi)) - pl;
    const double l = double(float(lo)), r = double(float(hi)) - l;
    const double top = levels;
    std::array<std::uint8_t, 256> out{};
    for (int q = 0; q <= levels; ++q) {
        const double h = pl + double(q) * pr / top;
        const double t = (h - l) / r * top;
        out[std::size_t(q)] = std::uint8_t(std::floor(std::clamp(t, 0.0, top) + 0.5));
    }
    return out;
}

void put_float(std::vector<std::uint8_t>& out, double v) {
    const float f = float(v);
    std::uint8_t b[4];
    std::memcpy(b, &f, 4);  // little-endian hosts (x86-64, arm64)
    out.insert(out.end(), b, b + 4);
}

}  // namespace

double max_sun_elevation_rad(double latitude_deg) {
    return (90.0 - std::max(0.0, std::abs(latitude_deg) - kObliquityDeg)) * std::numbers::pi / 180.0;
}

std::vector<SunBand> sun_bands(double latitude_deg, int directions, double grid_north_deg) {
    const double deg = std::numbers::pi / 180.0;
    const double phi = latitude_deg * deg;
    // Per interval between adjacent directions: the sun's lowest and highest elevation there.
    std::vector<double> lo(std::size_t(directions), 1e9), hi(std::size_t(directions), -1e9);
    const double step = 360.0 / directions;
    for (double decl = -kObliquityDeg; decl <= kObliquityDeg + 1e-9; decl += 0.25) {
        const double d = decl * deg;
        for (double hour = -180.0; hour < 180.0; hour += 0.05) {
            const double h = hour * deg;
            const double sin_el = std::sin(phi) * std::sin(d) + std::cos(phi) * std::cos(d) * std::cos(h);
            const double el = std::asin(std::clamp(sin_el, -1.0, 1.0));
            if (el < -2.0 * deg) continue;
            // Clockwise from north, then on the grid (whose directions are stored).
            double az = std::atan2(std::sin(h), std::cos(h) * std::sin(phi) - std::tan(d) * std::cos(phi)) / deg + 180.0;
            az = std::fmod(az + grid_north_deg + 720.0, 360.0);
            const std::size_t i = std::size_t(int(std::floor(az / step)) % directions);
            lo[i] = std::min(lo[i], el), hi[i] = std::max(hi[i], el);
        }
    }
    // A direction's band covers both intervals it bounds (the reader interpolates across them).
    std::vector<SunBand> out;
    for (int d = 0; d < directions; ++d) {
        const std::size_t before = std::size_t((d + directions - 1) % directions), after = std::size_t(d);
        const double l = std::min(lo[before], lo[after]), h = std::max(hi[before], hi[after]);
        if (h < l) continue;  // the sun never shines from either side
        out.push_back({d, l, h});
    }
    return out;
}

namespace {

void put_u16(std::vector<std::uint8_t>& out, int v) {
    out.push_back(std::uint8_t(v & 255)), out.push_back(std::uint8_t((v >> 8) & 255));
}
void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int b = 0; b < 4; ++b) out.push_back(std::uint8_t((v >> (8 * b)) & 255));
}

}  // namespace

std::vector<std::uint8_t> encode_lightable_tile(const LightableTexels& tx, const LightablePixels& px,
                                                const LightableEncoding& e) {
    const int ch = lightable_channels(e.directions);
    const std::size_t n = std::size_t(tx.width) * std::size_t(tx.height);
    const int k_count = std::clamp(e.components, 1, kLightTransfer);
    auto at = [&](std::size_t t, int c) { return double(tx.values[t * std::size_t(ch) + std::size_t(c)]); };
    std::vector<std::uint8_t> valid(n, 0);
    for (std::size_t t = 0; t < n; ++t) {
        bool finite = true;
        for (int c = 0; c < ch && finite; ++c) finite = std::isfinite(at(t, c));
        valid[t] = finite;
    }

    // The transfer's mean and principal components over the window's texels.
    std::array<double, kLightTransfer> mean{};
    std::size_t count = 0;
    for (std::size_t t = 0; t < n; ++t)
        if (valid[t]) {
            ++count;
            for (int i = 0; i < kLightTransfer; ++i) mean[std::size_t(i)] += at(t, kLightTransferAt + i);
        }
    for (double& m : mean) m = count ? m / double(count) : 0.0;
    Matrix9 cov{}, basis{};
    for (std::size_t t = 0; t < n; ++t) {
        if (!valid[t]) continue;
        double d[kLightTransfer];
        for (int i = 0; i < kLightTransfer; ++i) d[i] = at(t, kLightTransferAt + i) - mean[std::size_t(i)];
        for (int i = 0; i < kLightTransfer; ++i)
            for (int j = 0; j < kLightTransfer; ++j) cov[i][j] += d[i] * d[j];
    }
    jacobi_eigen(cov, basis);
    std::array<int, kLightTransfer> order{};
    for (int i = 0; i < kLightTransfer; ++i) order[std::size_t(i)] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return cov[a][a] > cov[b][b]; });

    // The albedo's range over the window, per channel.
    std::array<double, 3> a_lo{1e9, 1e9, 1e9}, a_hi{-1e9, -1e9, -1e9};
    for (std::size_t t = 0; t < n; ++t)
        if (valid[t])
            for (std::size_t c = 0; c < 3; ++c) {
                const double a = at(t, kLightAlbedoAt + int(c));
                a_lo[c] = std::min(a_lo[c], a), a_hi[c] = std::max(a_hi[c], a);
            }
    for (std::size_t c = 0; c < 3; ++c)
        if (!(a_hi[c] >= a_lo[c])) a_lo[c] = a_hi[c] = 0.0;
    // The bounce's sun part, per coefficient.
    std::array<double, kLightBounce> b_lo{}, b_hi{};
    b_lo.fill(1e9), b_hi.fill(-1e9);
    for (std::size_t t = 0; t < n; ++t)
        if (valid[t])
            for (std::size_t i = 0; i < std::size_t(kLightBounce); ++i) {
                const double b = at(t, kLightBounceAt + int(i));
                b_lo[i] = std::min(b_lo[i], b), b_hi[i] = std::max(b_hi[i], b);
            }
    for (std::size_t i = 0; i < std::size_t(kLightBounce); ++i)
        if (!(b_hi[i] >= b_lo[i])) b_lo[i] = b_hi[i] = 0.0;

    std::vector<float> w(n * std::size_t(k_count), 0.0f);
    std::vector<double> w_lo(std::size_t(k_count), 0.0), w_hi(std::size_t(k_count), 0.0);
    const std::size_t planes = e.bands.size();
    std::vector<double> h_lo(planes, 1e9), h_hi(planes, -1e9);
    for (std::size_t t = 0; t < n; ++t) {
        if (!valid[t]) continue;
        for (int k = 0; k < k_count; ++k) {
            double sum = 0;
            for (int i = 0; i < kLightTransfer; ++i)
                sum += basis[i][order[std::size_t(k)]] * (at(t, kLightTransferAt + i) - mean[std::size_t(i)]);
            w[t * std::size_t(k_count) + std::size_t(k)] = float(sum);
            w_lo[std::size_t(k)] = std::min(w_lo[std::size_t(k)], sum), w_hi[std::size_t(k)] = std::max(w_hi[std::size_t(k)], sum);
        }
        for (std::size_t j = 0; j < planes; ++j) {
            const double h = at(t, kLightHorizonAt + e.bands[j].direction);
            h_lo[j] = std::min(h_lo[j], h), h_hi[j] = std::max(h_hi[j], h);
        }
    }
    // Each plane spends its 8 bits on the sun's band in its direction: a horizon below the
    // band's foot lets every sun there through, one above its top hides it; both are clamped.
    for (std::size_t j = 0; j < planes; ++j) {
        const double margin = kBandMarginRad;
        h_lo[j] = std::max({h_lo[j], e.bands[j].lowest_rad - margin, kLowestHorizonRad});
        h_hi[j] = std::min(h_hi[j], e.bands[j].highest_rad + margin);
        if (!(h_hi[j] > h_lo[j] + 1e-4)) h_hi[j] = h_lo[j] + 1e-4;
    }

    const int size = px.size;
    const int width = std::max(size, tx.width);
    const int levels = kHorizonLevels;
    std::vector<std::uint8_t> header = {'T', 'S', 'L', '1', 3, std::uint8_t(k_count)};
    put_u16(header, e.directions);
    put_u16(header, int(planes));
    put_u16(header, size);
    put_u16(header, 0);  // header rows, below
    put_u16(header, width);
    header.push_back(px.separable ? 1 : 0);
    header.push_back(std::uint8_t(px.grid_step));
    put_u32(header, std::uint32_t(tx.level_width)), put_u32(header, std::uint32_t(tx.level_height));
    put_u32(header, std::uint32_t(tx.x0)), put_u32(header, std::uint32_t(tx.y0));
    put_u16(header, tx.width), put_u16(header, tx.height);
    put_u16(header, kHorizonKeyInterval);
    put_u16(header, levels);
    for (const SunBand& b : e.bands) put_u16(header, b.direction);
    while (header.size() % 4) header.push_back(0);
    for (std::size_t j = 0; j < planes; ++j) put_float(header, h_lo[j]), put_float(header, h_hi[j]);
    for (double v : a_lo) put_float(header, v);
    for (double v : a_hi) put_float(header, v);
    for (double m : mean) put_float(header, m);
    for (int k = 0; k < k_count; ++k)
        for (int i = 0; i < kLightTransfer; ++i) put_float(header, basis[i][order[std::size_t(k)]]);
    for (double v : w_lo) put_float(header, v);
    for (double v : w_hi) put_float(header, v);
    for (double v : b_lo) put_float(header, v);
    for (double v : b_hi) put_float(header, v);
    if (px.separable) {
        for (float v : px.x) put_float(header, v);
        for (float v : px.y) put_float(header, v);
    } else {
        // x then y per node, as the header comment says and the reader reads.
        for (std::size_t k = 0; k < px.x.size(); ++k) put_float(header, px.x[k]), put_float(header, px.y[k]);
    }
    const int header_rows = int((header.size() + std::size_t(width) - 1) / std::size_t(width));
    header[12] = std::uint8_t(header_rows & 255), header[13] = std::uint8_t(header_rows >> 8);

    // valid, normal (3), albedo (3), transfer (K), bounce (4), horizons (P)
    constexpr int kFirstTransferPlane = 7;
    const int first_bounce = kFirstTransferPlane + k_count;
    const int texel_planes = first_bounce + kLightBounce + int(planes);
    const std::size_t rows = std::size_t(header_rows) + std::size_t(size) + std::size_t(texel_planes) * std::size_t(tx.height);
    std::vector<std::uint8_t> image(rows * std::size_t(width), 0);
    std::copy(header.begin(), header.end(), image.begin());
    std::uint8_t* coverage = image.data() + std::size_t(header_rows) * std::size_t(width);
    for (int r = 0; r < size; ++r)
        for (int c = 0; c < size; ++c)
            coverage[std::size_t(r) * std::size_t(width) + std::size_t(c)] = px.covered[std::size_t(r) * std::size_t(size) + std::size_t(c)] ? 255 : 0;
    // Texel t of plane k. The horizon planes interleave by texel row (row r of direction j is
    // image row r * P + j of their block), so PNG's Up filter predicts each horizon from the
    // same texel's in the previous direction: neighbouring azimuths differ little.
    const int first_horizon = first_bounce + kLightBounce;
    auto texel = [&](int k, std::size_t t) -> std::uint8_t& {
        const std::size_t r = t / std::size_t(tx.width);
        const std::size_t row = std::size_t(header_rows) + std::size_t(size) +
                                (k < first_horizon ? std::size_t(k) * std::size_t(tx.height) + r
                                                   : std::size_t(first_horizon) * std::size_t(tx.height) +
                                                         r * planes + std::size_t(k - first_horizon));
        return image[row * std::size_t(width) + t % std::size_t(tx.width)];
    };
    for (std::size_t t = 0; t < n; ++t) {
        if (!valid[t]) continue;
        texel(0, t) = 255;
        double nx = at(t, kLightNormal), ny = at(t, kLightNormal + 1), nz = at(t, kLightNormal + 2);
        const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
        if (len > 0) nx /= len, ny /= len;
        const int qx = int(std::lround(std::clamp((nx + 1) * 0.5, 0.0, 1.0) * 4095));
        const int qy = int(std::lround(std::clamp((ny + 1) * 0.5, 0.0, 1.0) * 4095));
        texel(1, t) = std::uint8_t(qx >> 4), texel(2, t) = std::uint8_t(qy >> 4);
        texel(3, t) = std::uint8_t(((qx & 15) << 4) | (qy & 15));
        for (std::size_t c = 0; c < 3; ++c) texel(4 + int(c), t) = quantise(at(t, kLightAlbedoAt + int(c)), a_lo[c], a_hi[c]);
        for (int k = 0; k < k_count; ++k)
            texel(kFirstTransferPlane + k, t) =
                quantise(w[t * std::size_t(k_count) + std::size_t(k)], w_lo[std::size_t(k)], w_hi[std::size_t(k)]);
        for (std::size_t i = 0; i < std::size_t(kLightBounce); ++i)
            texel(first_bounce + int(i), t) = quantise(at(t, kLightBounceAt + int(i)), b_lo[i], b_hi[i]);
        for (std::size_t j = 0; j < planes; ++j)
            texel(first_horizon + int(j), t) = quantise(at(t, kLightHorizonAt + e.bands[j].direction), h_lo[j], h_hi[j], levels);
    }
    // Each horizon plane but the key ones keeps its difference from its prediction by the
    // previous stored direction's (predicted_horizon_codes), last plane first so each
    // prediction reads the plane before it unchanged.
    for (std::size_t j = planes; j-- > 1;) {
        if (!predicted_plane(e.bands, j)) continue;
        const std::array<std::uint8_t, 256> predict = predicted_horizon_codes(h_lo[j - 1], h_hi[j - 1], h_lo[j], h_hi[j], levels);
        for (std::size_t t = 0; t < n; ++t) {
            std::uint8_t& q = texel(first_horizon + int(j), t);
            q = std::uint8_t(q - predict[texel(first_horizon + int(j) - 1, t)]);
        }
    }
    raster::PngEncoding encoding;
    encoding.deflater = raster::Deflater::libdeflate;
    encoding.level = e.deflate_level;
    return raster::encode_png(width, int(rows), 1, image.data(), encoding);
}

}  // namespace ts::tiles
