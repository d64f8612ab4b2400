#include "core/raster/image_io_plugin/float_image_io.hpp"

#include <dlfcn.h>

#include <array>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <string>
#include <system_error>

#include "core/raster/image_io_plugin/image_io_plugin_api.h"
#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"

#ifndef TS_IMAGE_IO_PLUGIN_NAME
#define TS_IMAGE_IO_PLUGIN_NAME "libterrashade_image_io.so"
#endif

namespace ts::raster {
namespace fs = std::filesystem;

namespace {

// The module's entry points once it is loaded; never unloaded (OIIO keeps threads and
// static state that must outlive any caller).
struct Plugin {
    fs::path path;
    decltype(&ts_image_io_read_float) read = nullptr;
    decltype(&ts_image_io_free) free_pixels = nullptr;
    decltype(&ts_image_io_write_exr) write_exr = nullptr;
    std::string error;  // why it could not be loaded (empty when loaded)
};

std::vector<fs::path> candidate_paths() {
    std::vector<fs::path> paths;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        paths.push_back(exe.parent_path() / TS_IMAGE_IO_PLUGIN_NAME);
        paths.push_back(exe.parent_path().parent_path() / "lib" / "terrashade" / TS_IMAGE_IO_PLUGIN_NAME);
    }
#ifdef TS_IMAGE_IO_PLUGIN_BUILD_PATH
    paths.emplace_back(TS_IMAGE_IO_PLUGIN_BUILD_PATH);
#endif
    return paths;
}

Plugin load_plugin() {
    Plugin plugin;
    std::string tried;
    for (const fs::path& candidate : candidate_paths()) {
        std::error_code ec;
        if (!fs::exists(candidate, ec)) {
            tried += (tried.empty() ? "" : ", ") + candidate.string();
            continue;
        }
        void* handle = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (handle == nullptr) {
            const char* why = ::dlerror();
            plugin.error = candidate.string() + ": cannot load the image module: " + (why ? why : "unknown error");
            return plugin;
        }
        using AbiFn = decltype(&ts_image_io_abi_version);
        auto abi = reinterpret_cast<AbiFn>(::dlsym(handle, "ts_image_io_abi_version"));
        plugin.read = reinterpret_cast<decltype(plugin.read)>(::dlsym(handle, "ts_image_io_read_float"));
        plugin.free_pixels = reinterpret_cast<decltype(plugin.free_pixels)>(::dlsym(handle, "ts_image_io_free"));
        plugin.write_exr = reinterpret_cast<decltype(plugin.write_exr)>(::dlsym(handle, "ts_image_io_write_exr"));
        if (abi == nullptr || plugin.read == nullptr || plugin.free_pixels == nullptr || plugin.write_exr == nullptr ||
            abi() != TS_IMAGE_IO_PLUGIN_ABI) {
            plugin.read = nullptr;
            plugin.error = candidate.string() + ": not a terrashade image module of this version";
            return plugin;
        }
        plugin.path = candidate;
        return plugin;
    }
    plugin.error = std::string(TS_IMAGE_IO_PLUGIN_NAME) +
                   ": image module (OpenImageIO, for .exr/.hdr) not found; tried " +
                   (tried.empty() ? "nothing" : tried);
    return plugin;
}

// Loaded once per process, on first use; thread-safe (C++ static initialisation).
const Plugin& plugin() {
    static const Plugin loaded = load_plugin();
    return loaded;
}

const Plugin& require_plugin() {
    const Plugin& p = plugin();
    if (p.read == nullptr) throw InputError(p.error);
    return p;
}

}  // namespace

fs::path image_io_plugin_path() {
    return require_plugin().path;
}

FloatPixels read_float_pixels(const fs::path& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) throw input_error(path.string(), "no such file");
    const Plugin& p = require_plugin();
    std::array<char, 512> error{};
    int width = 0;
    int height = 0;
    int channels = 0;
    float* pixels = nullptr;
    if (p.read(path.c_str(), &width, &height, &channels, &pixels, error.data(), error.size()) != 0 ||
        pixels == nullptr) {
        throw input_error(path.string(), std::string("cannot read image: ") + error.data());
    }
    std::unique_ptr<float, decltype(p.free_pixels)> owned(pixels, p.free_pixels);
    FloatPixels image;
    image.width = width;
    image.height = height;
    image.channels = channels;
    image.data.assign(pixels, pixels + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                                           static_cast<std::size_t>(channels));
    return image;
}

FloatImage read_float_image(const fs::path& path) {
    const FloatPixels in = read_float_pixels(path);
    const std::size_t count = static_cast<std::size_t>(in.width) * static_cast<std::size_t>(in.height);
    const std::size_t nch = static_cast<std::size_t>(in.channels);
    FloatImage image;
    image.width = in.width;
    image.height = in.height;
    image.rgb.resize(count * 3);
    for (std::size_t p = 0; p < count; ++p)
        for (std::size_t c = 0; c < 3; ++c) image.rgb[p * 3 + c] = in.data[p * nch + (nch >= 3 ? c : 0)];
    return image;
}

void write_float_image_exr(const fs::path& path, int width, int height, int channels, const float* data,
                           bool full_float) {
    if (width <= 0 || height <= 0 || channels < 1 || channels > 4 || data == nullptr) {
        throw input_error(path.string(), "bad image size or channel count for EXR output");
    }
    const Plugin& p = require_plugin();
    write_atomically(path, [&](const fs::path& tmp) {
        std::array<char, 512> error{};
        if (p.write_exr(tmp.c_str(), width, height, channels, data, full_float ? 0 : 1, error.data(), error.size()) !=
            0) {
            throw input_error(path.string(), std::string("cannot write EXR: ") + error.data());
        }
    });
}

}  // namespace ts::raster
