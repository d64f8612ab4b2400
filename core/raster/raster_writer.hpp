#pragma once
// Raster outputs, each written atomically (ts::write_atomically): a half-written file never
// replaces a good one.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/geo/georef.hpp"

namespace ts::raster {

// float32 GeoTIFF (.tif/.tiff): `bands` band-sequential planes of width*height, row-major,
// georeferenced like `georef` (gdalinfo shows the same CRS and corners as the input); NaN is
// nodata (GDAL_NODATA "nan"); band_names, if given, become GDAL band descriptions.
void write_float_raster(const std::filesystem::path& path, int width, int height, int bands, const float* data,
                        const geo::Georef& georef, const std::vector<std::string>& band_names = {});

// 8-bit image by extension: .png (libpng) or .tif/.tiff (GeoTIFF, georeferenced when
// georef != nullptr); channels 1 (grey), 2 (grey + alpha), 3 (RGB) or 4 (RGBA), interleaved, row-major;
// `nodata` becomes the GDAL_NODATA tag of a .tif (gdaldem hillshade writes 0).
void write_u8_image(const std::filesystem::path& path, int width, int height, int channels, const std::uint8_t* data,
                    const geo::Georef* georef, std::optional<int> nodata = std::nullopt);

}  // namespace ts::raster
