#pragma once
// Small files the DEM tests write for themselves (good and deliberately broken ones).
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

namespace ts::dem::test_files {

// A fresh, empty directory under a per-process temp folder that is removed when the process ends.
inline std::filesystem::path fresh_dir(const std::string& name) {
    struct Root {
        std::filesystem::path path = std::filesystem::temp_directory_path() / ("ts_dem_" + std::to_string(::getpid()));
        ~Root() {
            std::error_code ec;
            std::filesystem::remove_all(path, ec);
        }
    };
    static const Root root;
    auto d = root.path / name;
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

void write_bytes(const std::filesystem::path& path, const std::string& bytes);

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
    double x0 = 10, y0 = 1, cell = 0.25;
};
void write_tiff(const std::filesystem::path& path, const TiffSpec& spec, const std::vector<std::uint8_t>& samples);

// Samples as bytes, native byte order (libtiff writes them as the host's order).
template <typename T>
std::vector<std::uint8_t> as_bytes(const std::vector<T>& v) {
    std::vector<std::uint8_t> out(v.size() * sizeof(T));
    std::memcpy(out.data(), v.data(), out.size());
    return out;
}

}  // namespace ts::dem::test_files
