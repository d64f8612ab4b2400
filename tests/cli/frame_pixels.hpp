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

// Every channel of a picture, 8-bit, interleaved; empty (width 0) if it cannot be read.
struct Pixels {
    int width = 0, height = 0, channels = 0;
    std::vector<unsigned char> data;
    unsigned char at(int c, int r, int ch) const {
        return data[(std::size_t(r) * std::size_t(width) + std::size_t(c)) * std::size_t(channels) + std::size_t(ch)];
    }
};

// 8-bit samples as OpenImageIO converts to them: clamped to 0..1, scaled and rounded (an 8-bit
// file's codes come back unchanged).
inline Pixels read_pixels(const std::filesystem::path& path) {
    const raster::FloatPixels f = read_float_pixels(path);
    Pixels p;
    p.width = f.width, p.height = f.height, p.channels = f.channels;
    p.data.resize(f.data.size());
    for (std::size_t i = 0; i < f.data.size(); ++i)
        p.data[i] = (unsigned char)std::lround(std::clamp(double(f.data[i]), 0.0, 1.0) * 255.0);
    return p;
}

// The first three channels, 8-bit (a grey picture's one channel three times).
inline std::vector<unsigned char> read_rgb(const std::filesystem::path& path, int& w, int& h) {
    const Pixels p = read_pixels(path);
    EXPECT_GT(p.width, 0) << path << " cannot be read as a picture";
    w = p.width, h = p.height;
    if (p.channels == 0) return {};
    std::vector<unsigned char> rgb(std::size_t(w) * std::size_t(h) * 3);
    const std::size_t n = std::size_t(p.channels);
    for (std::size_t i = 0; i < std::size_t(w) * std::size_t(h); ++i)
        for (std::size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = p.data[i * n + (n >= 3 ? c : 0)];
    return rgb;
}

}  // namespace ts::cli_test
