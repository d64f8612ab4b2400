#include "core/raster/png_writer.hpp"

#include <png.h>

#include <string>

#include "core/util/error.hpp"

namespace ts::raster {

void write_png(const std::filesystem::path& file, const std::filesystem::path& shown_path, int width, int height,
               int channels, const std::uint8_t* data) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(width);
    image.height = static_cast<png_uint_32>(height);
    switch (channels) {
        case 1: image.format = PNG_FORMAT_GRAY; break;
        case 3: image.format = PNG_FORMAT_RGB; break;
        case 4: image.format = PNG_FORMAT_RGBA; break;
        default: throw input_error(shown_path.string(), "a PNG has 1, 3 or 4 channels, not " + std::to_string(channels));
    }
    const png_int_32 row_stride = static_cast<png_int_32>(width * channels);
    if (!png_image_write_to_file(&image, file.c_str(), 0, data, row_stride, nullptr)) {
        const std::string why = image.message;
        png_image_free(&image);
        throw input_error(shown_path.string(), "writing PNG failed: " + why);
    }
}

}  // namespace ts::raster
