#pragma once
// Reading one DEM file. The format is chosen by content (TIFF and zip magic bytes, the exact
// byte count of an SRTM tile), so a mislabelled file still reads or fails with a clear message.
// Every failure is a ts::InputError "path: problem".
#include <cstddef>
#include <filesystem>
#include <string>

#include "core/dem/dem.hpp"

namespace ts::dem {

// Any supported file: .hgt, .hgt.zip, GeoTIFF. Voids are NaN with void_mask set; not filled.
Dem read_dem(const std::filesystem::path& path);

// SRTM .hgt: raw big-endian int16, 1201^2 (3") or 3601^2 (1"), SW corner from the file name.
Dem read_hgt(const std::filesystem::path& path);
// The same from bytes already in memory; `name` gives the corner, `source` names the file in errors.
Dem read_hgt_bytes(const std::string& bytes, const std::string& name, const std::string& source);
// A zip archive holding one .hgt (as USGS/NASA distribute them).
Dem read_hgt_zip(const std::filesystem::path& path);
// GeoTIFF through libtiff + libgeotiff.
Dem read_geotiff(const std::filesystem::path& path);

}  // namespace ts::dem
