#pragma once
// Float (HDR) image input/output through OpenImageIO, loaded lazily: OIIO lives in the module
// libterrashade_image_io.so, dlopen'ed on the first call, because linking it into terrashade
// would make every command load its hundreds of shared libraries at start-up (see
// png_writer.hpp).
// The module is looked for next to the running executable (/proc/self/exe), then in
// ../lib/terrashade/ beside it, then at its build-tree path compiled in.
#include <filesystem>
#include <vector>

namespace ts::raster {

// Interleaved linear RGB floats, row-major from the top row.
struct FloatImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // width * height * 3

    const float* pixel(int col, int row) const {
        return &rgb[(static_cast<std::size_t>(row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(col)) *
                    3];
    }
};

// Every channel of an image as interleaved floats, row-major from the top row; integer samples
// scaled as OpenImageIO scales them (0..1 for unsigned ones: an 8-bit code k is k / 255).
struct FloatPixels {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> data;  // width * height * channels
};

// Reads the first subimage of any image OpenImageIO reads, every channel. Throws ts::InputError
// "path: problem" for a missing or unreadable file or a missing image module.
FloatPixels read_float_pixels(const std::filesystem::path& path);

// Reads any image OpenImageIO reads (.exr, .hdr, ...) as float RGB (grey replicated, alpha
// dropped). Throws ts::InputError "path: problem" for a missing or unreadable file or a missing
// image module.
FloatImage read_float_image(const std::filesystem::path& path);

// Writes `channels` (1..4: Y, YA, RGB, RGBA) interleaved floats, top row first, as OpenEXR
// (zip compression; half floats unless full_float), atomically (temporary name, then rename).
// Throws ts::InputError on failure.
void write_float_image_exr(const std::filesystem::path& path, int width, int height, int channels, const float* data,
                           bool full_float = false);

// Where the image module was found (loading it if needed). Throws ts::InputError if nowhere.
std::filesystem::path image_io_plugin_path();

}  // namespace ts::raster
