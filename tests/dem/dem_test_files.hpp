#pragma once
// Small files the DEM tests write for themselves (good and deliberately broken ones).
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/scratch_dir.hpp"

namespace ts::dem::test_files {

// A fresh, empty directory under a per-process temp folder that is removed when the process ends.
using ts::test::fresh_dir;

void write_bytes(const std::filesystem::path& path, const std::string& bytes);

// A zip archive holding one entry `entry` with `content` (libzip).
void write_zip(const std::filesystem::path& path, const std::string& entry, const std::string& content);

// How many of a TIFF's tiles or strips have no bytes (sparse).
int sparse_blocks(const std::filesystem::path& path);

// A 1201x1201 SRTM3 tile of big-endian int16 where height = col + row, with `voids` cells set to -32768.
std::string synthetic_hgt(const std::vector<std::pair<int, int>>& voids = {});

// A single-strip or tiled TIFF from raw samples; spp samples per pixel, optionally with GeoKeys:
// epsg > 0 writes that code as ProjectedCSTypeGeoKey (geographic when geographic=true), epsg < 0
// writes no GeoKeys and no tiepoints at all.
struct TiffSpec {
    int width = 4, height = 3, spp = 1, bits = 16;
    int sample_format = 2;  // SAMPLEFORMAT_INT
    bool tiled = false;
    int epsg = 4326;
    bool geographic = true;
    bool pixel_is_point = false;
    std::string nodata;  // GDAL_NODATA text, empty for none
    std::string copyright;  // TIFFTAG_COPYRIGHT, empty for none
    double x0 = 10, y0 = 1, cell = 0.25;
};
void write_tiff(const std::filesystem::path& path, const TiffSpec& spec, const std::vector<std::uint8_t>& samples);

// A georeferenced int16 TIFF whose header claims width x height cells while its blocks hold
// only `payload` bytes each (raw, whatever `compression` says): one strip of all rows, or
// tiles of `tile` x `tile` cells when tile > 0. The file is a few hundred bytes (strip) or
// a few hundred KB (tiles) while the raster it claims is gigabytes.
void write_lying_tiff(const std::filesystem::path& path, int width, int height, int compression, int tile,
                      const std::string& payload);

// Sets tag `tag` (SHORT or LONG, count 1) in the first IFD of a classic little-endian TIFF
// held in `bytes`, as a corrupt header would have it; false if the tag is not there.
// Header-only, so the CLI tests use it too.
inline bool patch_tiff_tag(std::string& bytes, std::uint16_t tag, std::uint32_t value) {
    auto u16 = [&](std::size_t at) { return std::uint16_t(std::uint8_t(bytes[at]) | std::uint8_t(bytes[at + 1]) << 8); };
    if (bytes.size() < 8 || bytes.compare(0, 2, "II") != 0) return false;
    std::uint32_t ifd = 0;
    std::memcpy(&ifd, bytes.data() + 4, 4);
    if (std::size_t(ifd) + 2 > bytes.size()) return false;
    const int n = u16(ifd);
    for (int i = 0; i < n && ifd + 2 + std::size_t(i + 1) * 12 <= bytes.size(); ++i) {
        const std::size_t e = ifd + 2 + std::size_t(i) * 12;
        if (u16(e) != tag) continue;
        if (u16(e + 2) == 3) {
            bytes[e + 8] = char(value & 0xff);
            bytes[e + 9] = char(value >> 8);
        } else {
            std::memcpy(bytes.data() + e + 8, &value, 4);
        }
        return true;
    }
    return false;
}

// Samples as bytes, native byte order (libtiff writes them as the host's order).
template <typename T>
std::vector<std::uint8_t> as_bytes(const std::vector<T>& v) {
    std::vector<std::uint8_t> out(v.size() * sizeof(T));
    std::memcpy(out.data(), v.data(), out.size());
    return out;
}

}  // namespace ts::dem::test_files
