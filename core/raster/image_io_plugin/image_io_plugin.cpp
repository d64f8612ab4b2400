// libterrashade_image_io: OpenImageIO behind the tiny C API of image_io_plugin_api.h.
#include <OpenImageIO/imageio.h>

#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <string>

#include "core/raster/image_io_plugin/image_io_plugin_api.h"

namespace {

int fail(char* error, size_t error_size, std::string message) {
    // One line: OIIO messages sometimes carry newlines.
    for (char& c : message) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    while (!message.empty() && message.back() == ' ') message.pop_back();
    if (error != nullptr && error_size > 0) {
        const size_t n = std::min(message.size(), error_size - 1);
        std::memcpy(error, message.data(), n);
        error[n] = '\0';
    }
    return 1;
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) int ts_image_io_abi_version(void) {
    return TS_IMAGE_IO_PLUGIN_ABI;
}

__attribute__((visibility("default"))) int ts_image_io_read_float(const char* path, int* width, int* height,
                                                                  int* channels, float** pixels, char* error,
                                                                  size_t error_size) {
    try {
        *pixels = nullptr;
        auto in = OIIO::ImageInput::open(path);
        if (!in) {
            std::string why = OIIO::geterror();
            return fail(error, error_size, why.empty() ? "cannot open as an image" : why);
        }
        const OIIO::ImageSpec& spec = in->spec();
        const int w = spec.width;
        const int h = spec.height;
        const int nch = spec.nchannels;
        if (w <= 0 || h <= 0 || nch <= 0 || spec.depth > 1) {
            return fail(error, error_size, "not a 2-D image with channels");
        }
        const size_t count = static_cast<size_t>(w) * static_cast<size_t>(h);
        if (count > (std::numeric_limits<size_t>::max() / 4) / sizeof(float) / static_cast<size_t>(nch)) {
            return fail(error, error_size, "image too large");
        }
        auto* out = static_cast<float*>(std::malloc(count * static_cast<size_t>(nch) * sizeof(float)));
        if (out == nullptr) return fail(error, error_size, "out of memory");
        if (!in->read_image(0, 0, 0, nch, OIIO::TypeDesc::FLOAT, out)) {
            std::free(out);
            return fail(error, error_size, in->geterror());
        }
        in->close();
        *width = w;
        *height = h;
        *channels = nch;
        *pixels = out;
        return 0;
    } catch (const std::exception& e) {
        return fail(error, error_size, e.what());
    } catch (...) {
        return fail(error, error_size, "unknown error in OpenImageIO");
    }
}

__attribute__((visibility("default"))) void ts_image_io_free(float* pixels) {
    std::free(pixels);
}

__attribute__((visibility("default"))) int ts_image_io_write_exr(const char* path, int width, int height, int channels,
                                                                 const float* data, int half_float, char* error,
                                                                 size_t error_size) {
    try {
        if (width <= 0 || height <= 0 || channels < 1 || channels > 4 || data == nullptr) {
            return fail(error, error_size, "bad image dimensions or channel count");
        }
        auto out = OIIO::ImageOutput::create("exr");
        if (!out) return fail(error, error_size, "OpenImageIO has no OpenEXR writer: " + OIIO::geterror());
        OIIO::ImageSpec spec(width, height, channels, half_float ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
        static const char* const kNames[4][4] = {
            {"Y", "", "", ""}, {"Y", "A", "", ""}, {"R", "G", "B", ""}, {"R", "G", "B", "A"}};
        spec.channelnames.clear();
        for (int c = 0; c < channels; ++c) spec.channelnames.emplace_back(kNames[channels - 1][c]);
        spec.alpha_channel = (channels == 2 || channels == 4) ? channels - 1 : -1;
        spec.attribute("compression", "zip");
        if (!out->open(path, spec)) return fail(error, error_size, out->geterror());
        if (!out->write_image(OIIO::TypeDesc::FLOAT, data)) return fail(error, error_size, out->geterror());
        if (!out->close()) return fail(error, error_size, out->geterror());
        return 0;
    } catch (const std::exception& e) {
        return fail(error, error_size, e.what());
    } catch (...) {
        return fail(error, error_size, "unknown error in OpenImageIO");
    }
}

}  // extern "C"
