#include "core/raster/image_writer_registry.hpp"

#include <algorithm>
#include <cctype>

namespace ts::raster {

const std::vector<ImageFormat>& image_formats() {
    //                                 writer                 geo    u8     float  alpha  bands  tiles
    static const std::vector<ImageFormat> formats = {
        {".png", ImageWriter::png, false, true, false, true, false, false},
        {".tif", ImageWriter::geotiff, true, true, true, true, true, false},
        {".tiff", ImageWriter::geotiff, true, true, true, true, true, false},
        {".exr", ImageWriter::exr, false, false, true, true, false, false},
        {".mbtiles", ImageWriter::mbtiles, true, true, false, true, false, true},
    };
    return formats;
}

const ImageFormat* find_image_format(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    for (const ImageFormat& f : image_formats())
        if (f.extension == ext) return &f;
    return nullptr;
}

bool written_as(const std::filesystem::path& path, ImageWriter writer) {
    const ImageFormat* f = find_image_format(path);
    return f && f->writer == writer;
}

std::vector<std::string> image_extensions(const std::function<bool(const ImageFormat&)>& wanted) {
    std::vector<std::string> out;
    for (const ImageFormat& f : image_formats())
        if (wanted(f)) out.emplace_back(f.extension);
    return out;
}

std::vector<std::string> u8_picture_extensions() {
    return image_extensions([](const ImageFormat& f) { return f.u8 && !f.tile_set; });
}

std::vector<std::string> picture_extensions() {
    return image_extensions([](const ImageFormat& f) { return !f.tile_set; });
}

std::vector<std::string> float_raster_extensions() {
    return image_extensions([](const ImageFormat& f) { return f.float32 && f.georeferenced && f.multi_band; });
}

std::vector<std::string> tile_set_extensions() {
    return image_extensions([](const ImageFormat& f) { return f.tile_set; });
}

}  // namespace ts::raster
