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

std::uint8_t quantise(double v, double lo, double hi) {
    const double t = hi > lo ? (v - lo) / (hi - lo) : 0.0;
    return std::uint8_t(std::lround(std::clamp(t, 0.0, 1.0) * 255.0));
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

std::vector<int> sun_directions(double latitude_deg, int directions) {
    const double deg = std::numbers::pi / 180.0;
    const double phi = latitude_deg * deg;
    std::vector<char> keep(std::size_t(directions), 0);
    const double step = 360.0 / directions;
    for (double decl = -kObliquityDeg; decl <= kObliquityDeg + 1e-9; decl += 0.5) {
        const double d = decl * deg;
        for (double hour = -180.0; hour < 180.0; hour += 0.25) {
            const double h = hour * deg;
            const double sin_el = std::sin(phi) * std::sin(d) + std::cos(phi) * std::cos(d) * std::cos(h);
            if (sin_el < std::sin(-2.0 * deg)) continue;
            // Clockwise from north.
            double az = std::atan2(std::sin(h), std::cos(h) * std::sin(phi) - std::tan(d) * std::cos(phi)) / deg + 180.0;
            az = std::fmod(az + 360.0, 360.0);
            const int lo = int(std::floor(az / step)) % directions;
            keep[std::size_t(lo)] = 1;
            keep[std::size_t((lo + 1) % directions)] = 1;
        }
    }
    std::vector<int> out;
    for (int i = 0; i < directions; ++i)
        if (keep[std::size_t(i)]) out.push_back(i);
    return out;
}

std::vector<std::uint8_t> encode_lightable_tile(int size, const float* values, const std::uint8_t* covered,
                                                const LightableEncoding& e) {
    const int ch = lightable_channels(e.directions);
    const std::size_t n = std::size_t(size) * std::size_t(size);
    const int k_count = std::clamp(e.components, 1, kLightTransfer);
    std::vector<std::uint8_t> has(n, 0);
    for (std::size_t p = 0; p < n; ++p) {
        if (!covered[p]) continue;
        bool finite = true;
        for (int c = 0; c < ch && finite; ++c) finite = std::isfinite(values[p * std::size_t(ch) + std::size_t(c)]);
        has[p] = finite;
    }
    auto at = [&](std::size_t p, int c) { return double(values[p * std::size_t(ch) + std::size_t(c)]); };

    // The transfer's mean and principal components over the tile's pixels.
    std::array<double, kLightTransfer> mean{};
    std::size_t count = 0;
    for (std::size_t p = 0; p < n; ++p)
        if (has[p]) {
            ++count;
            for (int i = 0; i < kLightTransfer; ++i) mean[std::size_t(i)] += at(p, kLightTransferAt + i);
        }
    for (double& m : mean) m = count ? m / double(count) : 0.0;
    Matrix9 cov{}, basis{};
    for (std::size_t p = 0; p < n; ++p) {
        if (!has[p]) continue;
        double d[kLightTransfer];
        for (int i = 0; i < kLightTransfer; ++i) d[i] = at(p, kLightTransferAt + i) - mean[std::size_t(i)];
        for (int i = 0; i < kLightTransfer; ++i)
            for (int j = 0; j < kLightTransfer; ++j) cov[i][j] += d[i] * d[j];
    }
    jacobi_eigen(cov, basis);
    std::array<int, kLightTransfer> order{};
    for (int i = 0; i < kLightTransfer; ++i) order[std::size_t(i)] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return cov[a][a] > cov[b][b]; });

    const int planes = 4 + k_count + int(e.planes.size());
    std::vector<float> w(n * std::size_t(k_count), 0.0f);
    std::vector<double> w_lo(std::size_t(k_count), 0.0), w_hi(std::size_t(k_count), 0.0);
    double h_lo = 1e9, h_hi = -1e9;
    for (std::size_t p = 0; p < n; ++p) {
        if (!has[p]) continue;
        for (int k = 0; k < k_count; ++k) {
            double s = 0;
            for (int i = 0; i < kLightTransfer; ++i)
                s += basis[i][order[std::size_t(k)]] * (at(p, kLightTransferAt + i) - mean[std::size_t(i)]);
            w[p * std::size_t(k_count) + std::size_t(k)] = float(s);
            w_lo[std::size_t(k)] = std::min(w_lo[std::size_t(k)], s), w_hi[std::size_t(k)] = std::max(w_hi[std::size_t(k)], s);
        }
        for (int d : e.planes) {
            const double h = at(p, kLightHorizonAt + d);
            h_lo = std::min(h_lo, h), h_hi = std::max(h_hi, h);
        }
    }
    h_lo = std::max(h_lo, kLowestHorizonRad);
    h_hi = std::min(h_hi, e.max_horizon_rad);
    if (!(h_hi > h_lo + 1e-4)) h_hi = h_lo + 1e-4;

    // The header.
    std::vector<std::uint8_t> header = {'T', 'S', 'L', '1', 1, std::uint8_t(k_count), std::uint8_t(e.directions),
                                        std::uint8_t(e.planes.size()), std::uint8_t(size & 255), std::uint8_t(size >> 8),
                                        0, 0};
    for (int d : e.planes) header.push_back(std::uint8_t(d));
    while (header.size() % 4) header.push_back(0);
    put_float(header, h_lo), put_float(header, h_hi);
    for (double m : mean) put_float(header, m);
    for (int k = 0; k < k_count; ++k)
        for (int i = 0; i < kLightTransfer; ++i) put_float(header, basis[i][order[std::size_t(k)]]);
    for (double v : w_lo) put_float(header, v);
    for (double v : w_hi) put_float(header, v);
    const int header_rows = int((header.size() + std::size_t(size) - 1) / std::size_t(size));
    header[10] = std::uint8_t(header_rows & 255), header[11] = std::uint8_t(header_rows >> 8);

    const std::size_t height = std::size_t(header_rows) + std::size_t(planes) * std::size_t(size);
    std::vector<std::uint8_t> image(height * std::size_t(size), 0);
    std::copy(header.begin(), header.end(), image.begin());
    auto plane = [&](int k) { return image.data() + (std::size_t(header_rows) + std::size_t(k) * std::size_t(size)) * std::size_t(size); };
    for (std::size_t p = 0; p < n; ++p) {
        if (!has[p]) continue;
        plane(0)[p] = 255;
        double nx = at(p, kLightNormal), ny = at(p, kLightNormal + 1), nz = at(p, kLightNormal + 2);
        const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
        if (len > 0) nx /= len, ny /= len;
        const int qx = int(std::lround(std::clamp((nx + 1) * 0.5, 0.0, 1.0) * 4095));
        const int qy = int(std::lround(std::clamp((ny + 1) * 0.5, 0.0, 1.0) * 4095));
        plane(1)[p] = std::uint8_t(qx >> 4), plane(2)[p] = std::uint8_t(qy >> 4);
        plane(3)[p] = std::uint8_t(((qx & 15) << 4) | (qy & 15));
        for (int k = 0; k < k_count; ++k)
            plane(4 + k)[p] = quantise(w[p * std::size_t(k_count) + std::size_t(k)], w_lo[std::size_t(k)], w_hi[std::size_t(k)]);
        for (std::size_t j = 0; j < e.planes.size(); ++j)
            plane(4 + k_count + int(j))[p] = quantise(at(p, kLightHorizonAt + e.planes[j]), h_lo, h_hi);
    }
    raster::PngEncoding encoding;
    encoding.deflater = raster::Deflater::isal;
    return raster::encode_png(size, int(height), 1, image.data(), encoding);
}

}  // namespace ts::tiles
