#include "core/dem/read_dem.hpp"

#include <stdexcept>

#include "core/dem/dem_format.hpp"

namespace ts::dem {

Dem read_dem(const std::filesystem::path& path) {
    switch (dem_format(path)) {
        case DemFormat::geotiff: return read_geotiff(path);
        case DemFormat::hgt_zip: return read_hgt_zip(path);
        case DemFormat::hgt: return read_hgt(path);
    }
    throw std::logic_error("read_dem: unhandled DemFormat");
}

}  // namespace ts::dem
