#include "core/dem/dem_layout.hpp"

namespace ts::dem {

DemLayout layout_of(const Dem& dem) {
    DemLayout layout;
    layout.width = dem.width;
    layout.height = dem.height;
    layout.georef = dem.georef;
    layout.vertical_datum = dem.vertical_datum;
    layout.height_unit = dem.height_unit;
    layout.credit = dem.credit;
    layout.source = dem.source;
    return layout;
}

Dem allocate_dem(const DemLayout& layout) {
    Dem dem;
    dem.width = layout.width;
    dem.height = layout.height;
    dem.z.assign(std::size_t(layout.width) * std::size_t(layout.height), 0.0f);
    dem.void_mask.assign(dem.z.size(), 0);
    dem.georef = layout.georef;
    dem.vertical_datum = layout.vertical_datum;
    dem.height_unit = layout.height_unit;
    dem.credit = layout.credit;
    dem.source = layout.source;
    return dem;
}

}  // namespace ts::dem
