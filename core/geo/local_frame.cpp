#include "core/geo/local_frame.hpp"

#include "core/geo/georef.hpp"

namespace ts::geo {

LocalFrame::LocalFrame(glm::dvec3 origin_lonlat_h)
    : origin_(origin_lonlat_h), cartesian_(origin_lonlat_h.y, origin_lonlat_h.x, origin_lonlat_h.z) {}

glm::dvec3 LocalFrame::to_enu(glm::dvec3 lonlat_h) const {
    glm::dvec3 enu;
    cartesian_.Forward(lonlat_h.y, lonlat_h.x, lonlat_h.z, enu.x, enu.y, enu.z);
    return enu;
}

glm::dvec3 LocalFrame::to_lonlat_h(glm::dvec3 enu) const {
    glm::dvec3 llh;
    cartesian_.Reverse(enu.x, enu.y, enu.z, llh.y, llh.x, llh.z);
    return llh;
}

glm::dvec3 LocalFrame::pixel_to_enu(const Georef& georef, double col, double row, double h) const {
    const glm::dvec2 ll = georef.pixel_to_lonlat(col, row);
    return to_enu({ll.x, ll.y, h});
}

LocalFrame LocalFrame::at_raster_centre(const Georef& georef, double h) {
    const glm::dvec2 ll = georef.pixel_to_lonlat(georef.width() * 0.5, georef.height() * 0.5);
    return LocalFrame({ll.x, ll.y, h});
}

}  // namespace ts::geo
