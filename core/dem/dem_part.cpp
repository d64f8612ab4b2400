#include "core/dem/dem_part.hpp"

#include <stdexcept>

#include "core/dem/dem_format.hpp"

namespace ts::dem {

std::unique_ptr<DemPart> open_dem_part(const std::filesystem::path& path, std::uint32_t key) {
    switch (dem_format(path)) {
        case DemFormat::geotiff: return open_geotiff_part(path, key);
        case DemFormat::hgt_zip: return open_hgt_zip_part(path, key);
        case DemFormat::hgt: return open_hgt_part(path);
    }
    throw std::logic_error("open_dem_part: unhandled DemFormat");
}

}  // namespace ts::dem
