#pragma once
// The height grid the horizon searches read from a Dem: true metric spacing per row
// (terrain::metric_view) and every texel the source marked as void turned into a hole (NaN),
// filled or not. The rule (docs/visibility.md): a void neither blocks nor receives; the
// surface next to it is interpolated from the valid texels only (surface_sampling.hpp).
#include <vector>

#include "core/dem/dem.hpp"
#include "core/terrain/height_grid.hpp"

namespace ts::visibility {

class VisibilityGrid {
public:
    explicit VisibilityGrid(const dem::Dem& dem);
    VisibilityGrid(const VisibilityGrid&) = delete;
    VisibilityGrid& operator=(const VisibilityGrid&) = delete;

    const terrain::HeightGrid& view() const { return view_; }

private:
    std::vector<float> z_;
    terrain::HeightGrid view_;
};

}  // namespace ts::visibility
