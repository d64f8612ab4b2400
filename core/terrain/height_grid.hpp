#pragma once
// A metric view of a DEM for the terrain algorithms: the heights as they are in memory plus
// the true ground spacing of each row in metres. On a geographic grid (SRTM) the east-west
// spacing shrinks with cos(latitude), so it is stored per row; algorithms that use one
// spacing for the whole grid are wrong away from the equator.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace ts::terrain {

struct HeightGrid {
    int width = 0;
    int height = 0;
    // Row-major, row 0 = north edge. Not owned: points into the Dem (or a test's vector),
    // which must outlive the view. NaN marks a void (a DEM read with --no-fill).
    std::span<const float> z;
    // 1 where the source had no data, even if the height was filled since; may be empty.
    std::span<const std::uint8_t> void_mask;
    // Ground distance in metres between the centres of neighbouring texels of row r:
    // dx_m[r] east-west, dy_m[r] north-south. Sizes: height.
    std::vector<double> dx_m;
    std::vector<double> dy_m;

    std::size_t index(int col, int row) const { return std::size_t(row) * std::size_t(width) + std::size_t(col); }
    float at(int col, int row) const { return z[index(col, row)]; }
    // True where there is no usable height (NaN).
    bool is_hole(int col, int row) const { return std::isnan(at(col, row)); }
    // True where the source had no data (filled or not).
    bool was_void(int col, int row) const { return !void_mask.empty() && void_mask[index(col, row)] != 0; }

    // A grid with the same spacing on every row (projected DEMs, tests).
    static HeightGrid uniform(int width, int height, std::span<const float> z, double dx_m, double dy_m) {
        HeightGrid g;
        g.width = width;
        g.height = height;
        g.z = z;
        g.dx_m.assign(std::size_t(height), dx_m);
        g.dy_m.assign(std::size_t(height), dy_m);
        return g;
    }
};

}  // namespace ts::terrain
