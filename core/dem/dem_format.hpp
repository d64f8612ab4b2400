#pragma once
// Which reader a DEM file needs, by content (TIFF and zip magic bytes, the exact byte count
// of an SRTM tile), so a mislabelled file still reads or fails with a clear message.
#include <filesystem>

namespace ts::dem {

enum class DemFormat { geotiff, hgt_zip, hgt };

// Throws ts::InputError "path: problem" for a missing, empty, unreadable or unrecognised file.
DemFormat dem_format(const std::filesystem::path& path);

}  // namespace ts::dem
