#pragma once
// The tiled height pyramid: level 0 is the DEM, level i+1 halves level i by a 2x2 box
// prefilter. Beside the mean pyramid sits a max pyramid (each texel the highest level-0 height
// beneath it), for conservative searches: a ray above the max of a coarse texel cannot hit
// anything inside it. Both are stored as TiledRaster (fixed-size tiles with halos, O(1) access).
//
// Sizes: level i+1 is ceil(w/2) x ceil(h/2); the last column/row of an odd level averages only
// the texels that exist. Voids (NaN) are skipped: the mean is over the valid texels of the 2x2
// block and the max ignores voids; a block with no valid texel stays NaN in both.
// Coordinates: texel (c, r) of level i covers level-0 texels [c*2^i, (c+1)*2^i); in texel-centre
// coordinates, level-0 x maps to level-i x' = (x + 0.5) / 2^i - 0.5 (to_level()).
#include <cstddef>
#include <vector>

#include "core/terrain/height_grid.hpp"
#include "core/terrain/tiled_raster.hpp"

namespace ts::terrain {

struct PyramidOptions {
    // Texels per tile side (a power of two). Smaller tiles waste less padding on small levels
    // and fit caches better; larger ones have less halo overhead ((T + 2h)^2 / T^2).
    int tile_size = 256;
    // Texels copied from neighbouring tiles on each side; >= 1 so a bilinear footprint never
    // straddles tiles. 2 leaves room for 3x3 stencils at a texel's east/south neighbour.
    int halo = 2;
    // Number of levels including level 0; 0 = down to a single texel.
    int max_levels = 0;
    // 0 = one thread per core.
    int threads = 0;
};

struct PyramidLevel {
    int index = 0;
    int width = 0, height = 0;
    // Level-0 texels per texel side of this level (2^index).
    int scale = 1;
    TiledRaster mean;
    // Empty at level 0, where the max equals the heights: read it through max_raster().
    TiledRaster max;
    // Ground spacing of each row of this level in metres (the level-0 spacing of the rows it
    // covers, averaged, times the scale).
    std::vector<double> dx_m, dy_m;

    float at(int col, int row) const { return mean.at(col, row); }
    const TiledRaster& max_raster() const { return index == 0 ? mean : max; }
    float max_at(int col, int row) const { return max_raster().at(col, row); }
    // Bilinear height at texel-centre coordinates of this level, clamped to the edges.
    float sample(float x, float y) const { return mean.bilinear(x, y); }
    // The same at level-0 texel-centre coordinates.
    float sample_level0(float x0, float y0) const { return mean.bilinear(to_level(x0), to_level(y0)); }
    // Void-skipping bilinear height (valid_bilinear.hpp) at level-0 texel-centre coordinates,
    // in double precision, clamped to this level's edges: what a marcher reading coarse levels
    // at positions along a level-0 ray needs. Mapping by a power of two is exact in double.
    float sample_level0_valid(double x0, double y0) const {
        return mean.bilinear_valid((x0 + 0.5) / scale - 0.5, (y0 + 0.5) / scale - 0.5);
    }
    float to_level(float level0_coord) const { return (level0_coord + 0.5f) / float(scale) - 0.5f; }
};

class HeightPyramid {
public:
    HeightPyramid() = default;
    // Builds every level from the grid. Throws std::invalid_argument on bad options.
    HeightPyramid(const HeightGrid& grid, const PyramidOptions& options = {});

    int level_count() const { return int(levels_.size()); }
    const PyramidLevel& level(int i) const { return levels_[std::size_t(i)]; }
    const PyramidOptions& options() const { return options_; }
    std::size_t memory_bytes() const;

    // Level-0 texel-centre position reached from (x0, y0) by moving east_m metres east and
    // north_m metres north on the ground. Uses the spacing at the mid-row of the move
    // (second-order accurate where spacing varies with latitude); a local approximation for
    // marching, not a geodesic.
    void offset_metric(float x0, float y0, double east_m, double north_m, float& x, float& y) const;

private:
    PyramidOptions options_;
    std::vector<PyramidLevel> levels_;
    std::vector<double> level0_dx_m_, level0_dy_m_;
};

// One 2x2 prefilter step on whole rasters (w x h -> ceil(w/2) x ceil(h/2)), as the pyramid does
// it. `use_max` picks the max instead of the mean. Exposed for tests and tools.
std::vector<float> downsample_2x2(const float* src, int w, int h, bool use_max, int threads = 0);

}  // namespace ts::terrain
