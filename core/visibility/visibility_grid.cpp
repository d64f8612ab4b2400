#include "core/visibility/visibility_grid.hpp"

#include <limits>

#include "core/terrain/dem_height_grid.hpp"

namespace ts::visibility {

VisibilityGrid::VisibilityGrid(const dem::Dem& dem) : z_(dem.z) {
    for (std::size_t i = 0; i < z_.size(); ++i)
        if (i < dem.void_mask.size() && dem.void_mask[i]) z_[i] = std::numeric_limits<float>::quiet_NaN();
    view_ = terrain::metric_view(dem);
    view_.z = z_;
}

}  // namespace ts::visibility
