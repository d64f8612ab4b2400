#pragma once
// A mean-height mip pyramid of a height grid for the pyramid horizon method: level l+1
// averages 2x2 texels of level l, over valid (non-void) texels only; a texel whose four
// sources are all voids stays a void. Kept local to visibility because it needs nothing but
// the means; core/terrain's tiled HeightPyramid serves the GPU path.
#include <vector>

#include "core/terrain/height_grid.hpp"

namespace ts::visibility {

class MeanPyramid {
public:
    explicit MeanPyramid(const terrain::HeightGrid& grid);

    int levels() const { return int(levels_.size()); }
    // Bilinear sample of `level` at a position given in level-0 texel-centre coordinates.
    float sample(int level, double col, double row) const;

private:
    struct Level {
        int width, height;
        std::vector<float> z;
    };
    std::vector<Level> levels_;
};

}  // namespace ts::visibility
