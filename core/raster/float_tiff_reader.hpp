#pragma once
// Reads back a float32 GeoTIFF of any number of bands (tiled or stripped, bands interleaved or
// separate), full resolution only: the shards of `insolation --shard` that `merge` joins
// (write_float_cog writes them).
#include <filesystem>
#include <string>
#include <vector>

#include "core/geo/georef.hpp"

namespace ts::raster {

struct FloatTiff {
    int width = 0, height = 0, bands = 0;
    std::vector<float> values;  // band-sequential planes of width*height, row-major
    geo::Georef georef;
    std::string image_description;  // "" when the file has none
    const float* band(int b) const { return values.data() + std::size_t(b) * std::size_t(width) * std::size_t(height); }
};

// Throws ts::InputError "path: problem" for a file that is not a georeferenced float32 TIFF,
// or past `max_values` samples in all.
FloatTiff read_float_tiff(const std::filesystem::path& path, std::size_t max_values);

}  // namespace ts::raster
