#pragma once
// A written picture's RGB bytes (OpenImageIO), for the CLI tests of commands that write frames.
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

}  // namespace ts::cli_test
