#pragma once
// The .hgt inside a zip archive (as USGS/NASA distribute SRTM tiles): found from the
// archive's directory alone, inflated only when its heights are wanted.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ts::dem {

struct HgtZipEntry {
    std::uint64_t index = 0;  // in the archive's directory
    std::uint64_t size = 0;   // inflated bytes, checked to be a tile's
    // "archive (entry)", for messages about the entry.
    std::string where;
    // The entry's file name, then the archive's: the tile's corner comes from the first that
    // names one (N00E011.hgt.zip may hold a plain "hgt" entry).
    std::string names;
};

// The first .hgt entry; throws ts::InputError "path: ..." for an unreadable archive, one with
// no .hgt, or an entry whose size is no tile's (before anything is inflated).
HgtZipEntry find_hgt_zip_entry(const std::filesystem::path& path);

// The entry's bytes, inflated (fewer than entry.size if the archive lies about it).
std::vector<unsigned char> inflate_hgt_zip_entry(const std::filesystem::path& path, const HgtZipEntry& entry);

}  // namespace ts::dem
