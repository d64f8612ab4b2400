#pragma once
// GDAL's per-band metadata in a TIFF (the GDAL_METADATA tag's XML): the descriptions and units
// gdalinfo shows for each band (GDALRasterBand::GetDescription / GetUnitType), written by the
// float GeoTIFF writers.
#include <string>
#include <vector>

namespace ts::raster {

// <GDALMetadata> with, for band b < bands, an Item role="description" from descriptions[b] and
// an Item role="unittype" from units[b] (each list may be shorter than bands, or empty; empty
// strings are left out). "" when there is nothing to write (the tag is then omitted).
std::string gdal_band_metadata_xml(int bands, const std::vector<std::string>& descriptions,
                                   const std::vector<std::string>& units = {});

}  // namespace ts::raster
