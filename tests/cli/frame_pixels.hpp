#pragma once
// A written picture's samples, for the CLI tests of commands that write pictures. Read through
// terrashade's own image module (core/raster/image_io_plugin: OpenImageIO, loaded on first use)
// rather than by linking OpenImageIO: every test case runs in its own process, and loading
// OpenImageIO's ~260 shared libraries at start-up cost each of them 0.3 s.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <vector>

#include <gtest/gtest.h>

#include "core/raster/image_io_plugin/float_image_io.hpp"

namespace ts::cli_test {

// Every channel of a picture as floats (integer samples scaled to 0..1, as OpenImageIO scales
// them); empty (width 0) if it cannot be read.
inline raster::FloatPixels read_float_pixels(const std::filesystem::path& path) {
    try {
        return raster::read_float_pixels(path);
    } catch (const std::exception&) {
        return {};
    }
}

// A picture's first three channels as floats (a grey picture's one channel three times), as
// terrashade reads pictures; empty (width 0) if it cannot be read.
inline raster::FloatImage read_float_rgb(const std::filesystem::path& path) {
    try {
        return raster::read_float_image(path);
    } catch (const std::exception&) {
        return {};
    }
}

// An 8-bit code as OpenImageIO converts a float to one: clamped to 0..1, scaled and rounded (an
// 8-bit file's codes come back unchanged).
inline unsigned char to_code(float v) {
    return (unsigned char)std::lround(std::clamp(double(v), 0.0, 1.0) * 255.0);
}

// Every channel of a picture, 8-bit, interleaved; empty (width 0) if it cannot be read.
struct Pixels {
    int width = 0, height = 0, channels = 0;
    std::vector<unsigned char> data;
    unsigned char at(int c, int r, int ch) const {
        return data[(std::size_t(r) * std::size_t(width) + std::size_t(c)) * std::size_t(channels) + std::size_t(ch)];
    }
};

inline Pixels read_pixels(const std::filesystem::path& path) {
    const raster::FloatPixels f = read_float_pixels(path);
    Pixels p;
    p.width = f.width, p.height = f.height, p.channels = f.channels;
    p.data.resize(f.data.size());
    std::transform(f.data.begin(), f.data.end(), p.data.begin(), to_code);
    return p;
}

// The first three channels, 8-bit (a grey picture's one channel three times).
inline std::vector<unsigned char> read_rgb(const std::filesystem::path& path, int& w, int& h) {
    const raster::FloatImage f = read_float_rgb(path);
    EXPECT_GT(f.width, 0) << path << " cannot be read as a picture";
    w = f.width, h = f.height;
    std::vector<unsigned char> rgb(f.rgb.size());
    std::transform(f.rgb.begin(), f.rgb.end(), rgb.begin(), to_code);
    return rgb;
}

}  // namespace ts::cli_test
