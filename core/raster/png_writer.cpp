#include "core/raster/png_writer.hpp"

#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <cstdio>
#include <string>
#include <vector>

#include "core/util/error.hpp"

namespace ts::raster {
namespace {

// libpng reports errors by longjmp back to the setjmp in encode(); no C++ object with a
// destructor lives between the two (they are all owned by write_png, outside).
struct ErrorState {
    std::jmp_buf jump;
    char message[256] = {};
};

void on_error(png_structp png, png_const_charp message) {
    auto* state = static_cast<ErrorState*>(png_get_error_ptr(png));
    std::snprintf(state->message, sizeof state->message, "%s", message ? message : "libpng error");
    std::longjmp(state->jump, 1);
}

void on_warning(png_structp, png_const_charp) {}

// Returns false (message in state) on a libpng error.
bool encode(std::FILE* file, int width, int height, int color_type, const PngEncoding& encoding,
            png_bytepp rows, ErrorState& state) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, on_error, on_warning);
    if (!png) {
        std::snprintf(state.message, sizeof state.message, "out of memory");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (setjmp(state.jump)) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    if (!info) png_error(png, "out of memory");
    png_init_io(png, file);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, color_type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(png, encoding.zlib_level);
    png_set_compression_strategy(png, Z_FILTERED);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, encoding.sub_filter ? PNG_FILTER_SUB : PNG_ALL_FILTERS);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

void write_png(const std::filesystem::path& file, const std::filesystem::path& shown_path, int width, int height,
               int channels, const std::uint8_t* data, const PngEncoding& encoding) {
    int color_type = 0;
    switch (channels) {
        case 1: color_type = PNG_COLOR_TYPE_GRAY; break;
        case 3: color_type = PNG_COLOR_TYPE_RGB; break;
        case 4: color_type = PNG_COLOR_TYPE_RGB_ALPHA; break;
        default: throw input_error(shown_path.string(), "a PNG has 1, 3 or 4 channels, not " + std::to_string(channels));
    }
    if (encoding.zlib_level < 0 || encoding.zlib_level > 9)
        throw input_error(shown_path.string(), "PNG zlib level must be 0..9");
    std::vector<png_bytep> rows(static_cast<std::size_t>(height));
    for (int y = 0; y < height; ++y)
        rows[std::size_t(y)] = const_cast<png_bytep>(data + std::size_t(y) * std::size_t(width) * std::size_t(channels));
    std::FILE* f = std::fopen(file.c_str(), "wb");
    if (!f) throw input_error(shown_path.string(), "writing PNG failed: cannot open the file");
    ErrorState state;
    const bool ok = encode(f, width, height, color_type, encoding, rows.data(), state);
    const bool closed = std::fclose(f) == 0;
    if (!ok) throw input_error(shown_path.string(), std::string("writing PNG failed: ") + state.message);
    if (!closed) throw input_error(shown_path.string(), "writing PNG failed: cannot finish the file (disk full?)");
}

}  // namespace ts::raster
