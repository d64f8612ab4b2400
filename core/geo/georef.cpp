#include "core/geo/georef.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <GeographicLib/Geodesic.hpp>

namespace ts::geo {

glm::dvec2 GeoTransform::invert(double x, double y) const {
    const double det = dx_col * dy_row - dx_row * dy_col;
    if (det == 0) throw std::logic_error("GeoTransform::invert: singular transform");
    const double ex = x - x0, ey = y - y0;
    return {(ex * dy_row - ey * dx_row) / det, (ey * dx_col - ex * dy_col) / det};
}

Georef::Georef(int width, int height, GeoTransform transform, std::shared_ptr<const Crs> crs, bool pixel_is_area)
    : width_(width), height_(height), transform_(transform), crs_(std::move(crs)), pixel_is_area_(pixel_is_area) {}

glm::dvec2 Georef::pixel_to_lonlat(double col, double row) const {
    return crs_->to_lonlat(transform_.apply(col, row));
}

glm::dvec2 Georef::lonlat_to_pixel(glm::dvec2 lonlat) const {
    return crs_to_pixel(crs_->from_lonlat(lonlat));
}

namespace {
// Geodesic distance on WGS84 between two lon/lat points. Latitudes are clamped to the poles:
// a global grid's outer rows lie half a cell beyond them (ETOPO1 spans 90.5S..90.5N).
double geodesic_m(glm::dvec2 a, glm::dvec2 b) {
    double s12 = 0;
    GeographicLib::Geodesic::WGS84().Inverse(std::clamp(a.y, -90.0, 90.0), a.x, std::clamp(b.y, -90.0, 90.0), b.x, s12);
    return s12;
}
}  // namespace

glm::dvec2 Georef::cell_size_m(double col, double row) const {
    // The centres of the two neighbours half a cell either side of (col, row), so the figure is
    // the true spacing of pixel centres there (it shrinks with cos(lat) on geographic grids).
    const double dx = geodesic_m(pixel_to_lonlat(col - 0.5, row), pixel_to_lonlat(col + 0.5, row));
    const double dy = geodesic_m(pixel_to_lonlat(col, row - 0.5), pixel_to_lonlat(col, row + 0.5));
    return {dx, dy};
}

double Georef::grid_azimuth_of_north_deg(double col, double row) const {
    if (crs_->is_geographic()) return 0.0;
    // A step of 0.001 degree of latitude (~110 m) towards the pole, or away from it beside it.
    const glm::dvec2 ll = pixel_to_lonlat(col, row);
    const double step = ll.y + 1e-3 > 90.0 ? -1e-3 : 1e-3;
    const glm::dvec2 p = lonlat_to_pixel({ll.x, ll.y + step});
    const glm::dvec2 cell = cell_size_m(col, row);
    const double sign = step > 0 ? 1.0 : -1.0;
    const double east = sign * (p.x - col) * cell.x, north = -sign * (p.y - row) * cell.y;
    const double a = std::atan2(east, north) * 180.0 / std::numbers::pi;
    // Grids whose columns run along meridians (Web Mercator) give 0 up to rounding.
    return std::abs(a) < 1e-7 ? 0.0 : a;
}

Georef Georef::window(int col0, int row0, int w, int h) const {
    GeoTransform t = transform_;
    const glm::dvec2 origin = transform_.apply(col0, row0);
    t.x0 = origin.x;
    t.y0 = origin.y;
    return Georef(w, h, t, crs_, pixel_is_area_);
}

}  // namespace ts::geo
