#pragma once
// The flythrough's metric frame over a DEM grid: level-0 texel-centre coordinates (col, row;
// row 0 north) <-> metres east and north of the grid's centre texel. East is col offset times
// the row's own east-west spacing (a geographic grid narrows towards the pole), north is the
// sum of the north-south spacings between rows; both are interpolated linearly between rows,
// which is what the terrain vertex shader does with the same per-row table.
#include <vector>

#include <glm/vec2.hpp>

#include "core/terrain/height_grid.hpp"

namespace ts::fly {

class GridFrame {
public:
    GridFrame() = default;
    explicit GridFrame(const terrain::HeightGrid& grid);

    int width() const { return width_; }
    int height() const { return height_; }
    double centre_col() const { return centre_col_; }
    // Per row: east-west spacing (m) and the row centre's north coordinate (m).
    const std::vector<double>& row_dx_m() const { return dx_; }
    const std::vector<double>& row_north_m() const { return north_; }

    // Metres (east, north) of a texel-centre position (rows clamped onto the grid for the spacing).
    glm::dvec2 to_metric(double col, double row) const;
    // The inverse: texel-centre (col, row) of a metric position.
    glm::dvec2 to_grid(double east_m, double north_m) const;
    // The row's interpolated spacing and north coordinate.
    double dx_at(double row) const;
    double north_at(double row) const;

private:
    int width_ = 0, height_ = 0;
    double centre_col_ = 0;
    std::vector<double> dx_, north_;
};

}  // namespace ts::fly
