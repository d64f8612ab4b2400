#include "app/bench/study/synthetic_mosaic.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"

namespace ts::app {
namespace {

// A lattice value in [0, 1) from integer coordinates (a 32-bit integer hash).
float lattice(std::int32_t x, std::int32_t y, std::uint32_t seed) {
    std::uint32_t h = std::uint32_t(x) * 0x8da6b343u ^ std::uint32_t(y) * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 13, h *= 0x5bd1e995u, h ^= h >> 15;
    return float(h & 0xffffffu) / float(0x1000000);
}

// Smoothly interpolated value noise at (x, y) in lattice units, in [0, 1).
float value_noise(double x, double y, std::uint32_t seed) {
    const double fx = std::floor(x), fy = std::floor(y);
    const auto ix = std::int32_t(fx), iy = std::int32_t(fy);
    const float tx = float(x - fx), ty = float(y - fy);
    const float sx = tx * tx * (3 - 2 * tx), sy = ty * ty * (3 - 2 * ty);
    const float a = lattice(ix, iy, seed), b = lattice(ix + 1, iy, seed);
    const float c = lattice(ix, iy + 1, seed), d = lattice(ix + 1, iy + 1, seed);
    return (a + (b - a) * sx) * (1 - sy) + (c + (d - c) * sx) * sy;
}

}  // namespace

// Ridged octaves: sharp crests where the noise crosses its middle, wavelengths from ~25 km
// down to ~4 texels, each octave's ridges weighted by the ones above (eroded-looking ranges).
float synthetic_height(int col, int row) {
    constexpr int kOctaves = 9;
    double wavelength = 800.0, amplitude = 1.0, sum = 0, norm = 0, weight = 1;
    for (int o = 0; o < kOctaves; ++o) {
        const float v = value_noise(double(col) / wavelength, double(row) / wavelength, std::uint32_t(o + 1));
        double ridge = 1.0 - std::abs(2.0 * v - 1.0);
        ridge *= ridge;
        sum += amplitude * ridge * weight;
        norm += amplitude;
        weight = std::min(1.0, 0.35 + ridge);
        wavelength *= 0.5, amplitude *= 0.5;
    }
    return float(3000.0 * sum / norm);
}

void synthetic_rows(int n, int row0, int rows, std::span<float> z, int threads) {
    if (z.size() != std::size_t(n) * std::size_t(std::max(rows, 0)))
        throw std::invalid_argument("synthetic_rows: z holds " + std::to_string(z.size()) + " heights, not rows * n");
    parallel_for(rows, thread_count(threads), [&](int r, int) {
        float* out = z.data() + std::size_t(r) * std::size_t(n);
        for (int col = 0; col < n; ++col) out[col] = synthetic_height(col, row0 + r);
    });
}

geo::Georef synthetic_georef(int n) {
    geo::GeoTransform t;
    const double cell = 1.0 / 3600.0;
    t.x0 = 40.0 - 0.5 * cell, t.dx_col = cell, t.dx_row = 0;
    t.y0 = 41.0 + 0.5 * cell, t.dy_col = 0, t.dy_row = -cell;
    return geo::Georef(n, n, t, geo::Crs::wgs84(), true);
}

dem::Dem synthetic_mosaic(int n, int threads) {
    if (n < 16 || n > 30001) throw InputError("synthetic:" + std::to_string(n) + ": a side of 16..30001 texels");
    dem::Dem d;
    d.width = d.height = n;
    d.z.resize(std::size_t(n) * std::size_t(n));
    d.void_mask.assign(d.z.size(), 0);
    synthetic_rows(n, 0, n, d.z, threads);
    d.georef = synthetic_georef(n);
    d.vertical_datum = "synthetic";
    d.source = "synthetic:" + std::to_string(n);
    return d;
}

}  // namespace ts::app
