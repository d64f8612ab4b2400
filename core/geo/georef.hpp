#pragma once
// Georeferencing of a raster: pixel <-> CRS <-> WGS84 lon/lat, and true metric cell sizes.
// Local ENU frames live in local_frame.hpp. Conventions (docs/architecture.md):
//  - pixel coordinates (col, row) are *edge* coordinates: the outer corner of the raster is
//    (0, 0) and the centre of pixel (i, j) is (i + 0.5, j + 0.5), as in GDAL. A PixelIsPoint
//    file is converted to this convention on reading (its tiepoint refers to a centre).
//  - lon/lat are degrees on WGS84, lon first.
#include <memory>
#include <string>

#include <glm/vec2.hpp>

#include "core/geo/crs.hpp"

namespace ts::geo {

// Affine pixel-edge -> CRS transform: x = x0 + col*dx_col + row*dx_row, y = y0 + col*dy_col + row*dy_row.
struct GeoTransform {
    double x0 = 0, dx_col = 1, dx_row = 0;
    double y0 = 0, dy_col = 0, dy_row = -1;

    glm::dvec2 apply(double col, double row) const {
        return {x0 + col * dx_col + row * dx_row, y0 + col * dy_col + row * dy_row};
    }
    glm::dvec2 invert(double x, double y) const;
};

class Georef {
public:
    Georef() = default;
    Georef(int width, int height, GeoTransform transform, std::shared_ptr<const Crs> crs, bool pixel_is_area);

    int width() const { return width_; }
    int height() const { return height_; }
    const GeoTransform& transform() const { return transform_; }
    const Crs& crs() const { return *crs_; }
    std::shared_ptr<const Crs> crs_ptr() const { return crs_; }
    bool valid() const { return crs_ != nullptr; }
    // As the file declared it (GTRasterTypeGeoKey); the transform is edge-based either way.
    bool pixel_is_area() const { return pixel_is_area_; }

    glm::dvec2 pixel_to_crs(double col, double row) const { return transform_.apply(col, row); }
    glm::dvec2 crs_to_pixel(glm::dvec2 xy) const { return transform_.invert(xy.x, xy.y); }
    glm::dvec2 pixel_to_lonlat(double col, double row) const;
    glm::dvec2 lonlat_to_pixel(glm::dvec2 lonlat) const;

    // Distance in metres on the ellipsoid between the centres of neighbouring pixels around
    // (col, row) (edge coordinates): {east-west, north-south}. For geographic grids this
    // varies with latitude; for projected grids it includes the projection's scale factor.
    glm::dvec2 cell_size_m(double col, double row) const;
    // The same at the raster centre.
    glm::dvec2 cell_size_m() const { return cell_size_m(width_ * 0.5, height_ * 0.5); }

    // Where true north points on the grid at (col, row) (edge coordinates): its azimuth in
    // degrees clockwise from the grid's up (-row), in the metric frame of cell_size_m, in
    // (-180, 180]. 0 on geographic and Web Mercator grids; on a projected grid the meridian
    // convergence, with its sign (UTM east of the central meridian: negative). A direction of
    // true azimuth A lies at A + this on the grid.
    double grid_azimuth_of_north_deg(double col, double row) const;
    // The same at the raster centre.
    double grid_azimuth_of_north_deg() const { return grid_azimuth_of_north_deg(width_ * 0.5, height_ * 0.5); }

    // A georef for the sub-window starting at pixel (col0, row0), of size w x h.
    Georef window(int col0, int row0, int w, int h) const;

private:
    int width_ = 0, height_ = 0;
    GeoTransform transform_;
    std::shared_ptr<const Crs> crs_;
    bool pixel_is_area_ = true;
};

}  // namespace ts::geo
