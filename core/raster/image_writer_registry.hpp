#pragma once
// Every raster and image file terrashade writes, chosen by its extension in this one place: the
// writer behind each extension and what it can hold. A command asks the registry which
// extensions an output takes (its IoPlan's list), which writer a path gets and whether the file
// will be georeferenced, so no command or writer tests an extension itself. A new format is one
// entry in image_writer_registry.cpp and its writer (docs/architecture.md).
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace ts::raster {

enum class ImageWriter {
    png,      // 8-bit PNG (png_writer.hpp)
    geotiff,  // GeoTIFF: 8-bit images, Cloud-Optimized maps, float rasters (raster_writer.hpp, cog_writer.hpp)
    exr,      // OpenEXR through the image module (image_io_plugin/float_image_io.hpp)
    mbtiles,  // a tile set in one SQLite file (core/tiles/mbtiles_file.hpp)
};

struct ImageFormat {
    std::string_view extension;  // lower case, with the dot
    ImageWriter writer;
    bool georeferenced;  // holds a CRS and the pixels' place in it
    bool u8;             // 8-bit display codes
    bool float32;        // 32-bit float samples (physical values, HDR radiance)
    bool alpha;          // an alpha channel (transparent off the DEM)
    bool multi_band;     // more than 4 bands (horizons, SH coefficients)
    bool tile_set;       // a pyramid of map tiles, not one picture
};

// The formats, in the order their extensions are listed to the user.
const std::vector<ImageFormat>& image_formats();

// The format of `path` by its extension, case-insensitive; null when none has it.
const ImageFormat* find_image_format(const std::filesystem::path& path);

// True when `path`'s extension is a format whose writer is `writer`.
bool written_as(const std::filesystem::path& path, ImageWriter writer);

// The extensions of the formats `wanted` accepts, in registry order (an IoPlan's list).
std::vector<std::string> image_extensions(const std::function<bool(const ImageFormat&)>& wanted);

// Lists the registry answers for the commands.
// One picture of 8-bit codes (hillshade, render's quick-looks): .png, .tif, .tiff.
std::vector<std::string> u8_picture_extensions();
// One picture in any format (render --out): 8-bit or float.
std::vector<std::string> picture_extensions();
// Georeferenced float rasters of any band count (visibility's values, render --sun-visibility).
std::vector<std::string> float_raster_extensions();
// Tile sets in one file (tiles --out FILE).
std::vector<std::string> tile_set_extensions();

}  // namespace ts::raster
