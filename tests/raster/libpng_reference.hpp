#pragma once
// libpng as the tests' reference: a decoder independent of OpenImageIO, and the encoder
// terrashade used before its own (libpng + zlib level 3, Sub filter), so a test can check that
// a picture decodes to the same pixels through either encoder.
#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace ts::test {

struct DecodedPng {
    int width = 0, height = 0, channels = 0;
    std::vector<std::uint8_t> pixels;  // interleaved, row-major from the top row
};

// Decodes an 8-bit grey, RGB or RGBA PNG with libpng's simplified API; throws on any error
// (libpng checks every chunk's CRC and the zlib stream's Adler-32).
inline DecodedPng decode_png_with_libpng(const std::filesystem::path& file) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, file.c_str()))
        throw std::runtime_error(file.string() + ": " + image.message);
    DecodedPng out;
    out.width = int(image.width), out.height = int(image.height);
    const bool colour = image.format & PNG_FORMAT_FLAG_COLOR, alpha = image.format & PNG_FORMAT_FLAG_ALPHA;
    out.channels = colour ? (alpha ? 4 : 3) : (alpha ? 2 : 1);
    image.format = colour ? (alpha ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB) : (alpha ? PNG_FORMAT_GA : PNG_FORMAT_GRAY);
    out.pixels.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, out.pixels.data(), 0, nullptr))
        throw std::runtime_error(file.string() + ": " + image.message);
    return out;
}

namespace detail {
struct PngJump {
    std::jmp_buf jump;
};
inline void on_png_error(png_structp png, png_const_charp) {
    std::longjmp(static_cast<PngJump*>(png_get_error_ptr(png))->jump, 1);
}
inline void on_png_warning(png_structp, png_const_charp) {}

// False on a libpng error (it longjmps back here; nothing with a destructor lives in between).
inline bool write_with_libpng(std::FILE* f, int width, int height, int colour_type, png_bytepp rows) {
    PngJump state;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, on_png_error, on_png_warning);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (setjmp(state.jump)) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    if (!info) png_error(png, "out of memory");
    png_init_io(png, f);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, colour_type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(png, 3);
    png_set_compression_strategy(png, Z_FILTERED);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}
}  // namespace detail

// The encoder of terrashade before its own: libpng, zlib level 3 with Z_FILTERED, the Sub
// filter on every row. Throws on failure.
inline void encode_png_with_libpng(const std::filesystem::path& file, int width, int height, int channels,
                                   const std::uint8_t* data) {
    const int colour_type = channels == 1 ? PNG_COLOR_TYPE_GRAY
                            : channels == 3 ? PNG_COLOR_TYPE_RGB
                                            : PNG_COLOR_TYPE_RGB_ALPHA;
    std::vector<png_bytep> rows(static_cast<std::size_t>(height));
    for (int y = 0; y < height; ++y)
        rows[std::size_t(y)] = const_cast<png_bytep>(data + std::size_t(y) * std::size_t(width) * std::size_t(channels));
    std::FILE* f = std::fopen(file.c_str(), "wb");
    if (!f) throw std::runtime_error(file.string() + ": cannot open");
    const bool ok = detail::write_with_libpng(f, width, height, colour_type, rows.data());
    const bool closed = std::fclose(f) == 0;
    if (!ok || !closed) throw std::runtime_error(file.string() + ": libpng failed");
}

}  // namespace ts::test
