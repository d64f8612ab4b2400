#include "core/terrain/dem_height_grid.hpp"

#include "core/util/error.hpp"

namespace ts::terrain {

HeightGrid metric_view(const dem::Dem& dem) {
    if (!dem.georef.valid()) throw input_error(dem.source, "has no georeferencing; cannot compute metric spacing");
    if (dem.z.size() != std::size_t(dem.width) * std::size_t(dem.height)) {
        throw input_error(dem.source, "height array does not match the raster size");
    }
    HeightGrid g;
    g.width = dem.width;
    g.height = dem.height;
    g.z = dem.z;
    g.void_mask = dem.void_mask;
    g.dx_m.resize(std::size_t(dem.height));
    g.dy_m.resize(std::size_t(dem.height));
    const double centre_col = dem.width * 0.5;
    for (int r = 0; r < dem.height; ++r) {
        const glm::dvec2 cell = dem.georef.cell_size_m(centre_col, r + 0.5);
        g.dx_m[std::size_t(r)] = cell.x;
        g.dy_m[std::size_t(r)] = cell.y;
    }
    return g;
}

}  // namespace ts::terrain
