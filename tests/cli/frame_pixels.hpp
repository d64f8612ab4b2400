#pragma once
// A written picture's bytes (OpenImageIO), for the CLI tests of commands that write pictures.
#include <cstddef>
#include <filesystem>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

namespace ts::cli_test {

inline std::vector<unsigned char> read_rgb(const std::filesystem::path& p, int& w, int& h) {
    auto in = OIIO::ImageInput::open(p.string());
    EXPECT_TRUE(in) << p;
    if (!in) return {};
    w = in->spec().width, h = in->spec().height;
    std::vector<unsigned char> px(std::size_t(w) * std::size_t(h) * 3);
    in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data());
    return px;
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
    Pixels p;
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) return p;
    p.width = in->spec().width, p.height = in->spec().height, p.channels = in->spec().nchannels;
    p.data.resize(std::size_t(p.width) * std::size_t(p.height) * std::size_t(p.channels));
    in->read_image(0, 0, 0, p.channels, OIIO::TypeDesc::UINT8, p.data.data());
    return p;
}

}  // namespace ts::cli_test
