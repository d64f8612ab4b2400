// The PNG encoder (core/raster/png_writer.cpp): every filter and the trial decode, through
// OpenImageIO and through libpng, to exactly the input bytes for 1, 3 and 4 channels, odd sizes
// and random or smooth pictures; the file's chunks are well formed; errors name the file and
// leave nothing behind.
#include "core/raster/png_writer.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include "core/raster/raster_writer.hpp"
#include "core/util/error.hpp"
#include "tests/raster/libpng_reference.hpp"

namespace fs = std::filesystem;
using namespace ts;

namespace {

struct TempDir {
    fs::path path = fs::temp_directory_path() / ("ts_png_writer_" + std::to_string(::getpid()));
    TempDir() { fs::create_directories(path); }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

std::vector<std::uint8_t> random_pixels(int w, int h, int channels, unsigned seed) {
    std::mt19937 rng(seed);
    std::vector<std::uint8_t> px(std::size_t(w) * std::size_t(h) * std::size_t(channels));
    for (auto& v : px) v = std::uint8_t(rng());
    return px;
}

// Smooth ramps with a little noise and flat patches: every filter predicts something well here.
std::vector<std::uint8_t> smooth_pixels(int w, int h, int channels, unsigned seed) {
    std::mt19937 rng(seed);
    std::vector<std::uint8_t> px(std::size_t(w) * std::size_t(h) * std::size_t(channels));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < channels; ++c) {
                const bool flat = (x / 37 + y / 23) % 3 == 0;
                const int v = flat ? 90 + 40 * c : (x * (c + 1) + 2 * y) / 3 + int(rng() % 3);
                px[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * std::size_t(channels) + std::size_t(c)] =
                    std::uint8_t(v);
            }
    return px;
}

std::vector<std::uint8_t> read_with_oiio(const fs::path& file, int w, int h, int channels) {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);  // RGBA as stored, not premultiplied
    auto in = OIIO::ImageInput::open(file.string(), &config);
    if (!in) return {};
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.width, w);
    EXPECT_EQ(spec.height, h);
    EXPECT_EQ(spec.nchannels, channels);
    EXPECT_EQ(spec.format, OIIO::TypeDesc::UINT8);
    std::vector<std::uint8_t> px(std::size_t(w) * std::size_t(h) * std::size_t(channels));
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, px.data())) return {};
    return px;
}

const char* name_of(raster::PngFilter f) {
    switch (f) {
        case raster::PngFilter::none: return "none";
        case raster::PngFilter::sub: return "sub";
        case raster::PngFilter::up: return "up";
        case raster::PngFilter::average: return "average";
        case raster::PngFilter::paeth: return "paeth";
        case raster::PngFilter::trial: return "trial";
    }
    return "?";
}

constexpr raster::PngFilter kAllFilters[] = {raster::PngFilter::none,    raster::PngFilter::sub,
                                             raster::PngFilter::up,      raster::PngFilter::average,
                                             raster::PngFilter::paeth,   raster::PngFilter::trial};

void expect_round_trip(const fs::path& file, int w, int h, int channels, const std::vector<std::uint8_t>& px,
                       const raster::PngEncoding& encoding, const std::string& what) {
    raster::write_png(file, file, w, h, channels, px.data(), encoding);
    EXPECT_EQ(read_with_oiio(file, w, h, channels), px) << what << " (OpenImageIO)";
    const test::DecodedPng d = test::decode_png_with_libpng(file);
    EXPECT_EQ(d.width, w) << what;
    EXPECT_EQ(d.height, h) << what;
    EXPECT_EQ(d.channels, channels) << what;
    EXPECT_EQ(d.pixels, px) << what << " (libpng)";
}

TEST(PngWriter, EveryFilterDecodesToTheInputBytes) {
    TempDir dir;
    struct Size {
        int w, h;
    };
    for (const Size s : {Size{1, 1}, Size{3, 7}, Size{500, 500}})
        for (int channels : {1, 3, 4})
            for (bool smooth : {false, true}) {
                const auto px = smooth ? smooth_pixels(s.w, s.h, channels, 7u) : random_pixels(s.w, s.h, channels, 11u);
                for (raster::PngFilter f : kAllFilters) {
                    raster::PngEncoding e;
                    e.filter = f;
                    const std::string what = std::to_string(s.w) + "x" + std::to_string(s.h) + "x" +
                                             std::to_string(channels) + (smooth ? " smooth " : " random ") +
                                             name_of(f);
                    expect_round_trip(dir.path / "p.png", s.w, s.h, channels, px, e, what);
                }
            }
}

TEST(PngWriter, EveryLevelDecodesToTheInputBytes) {
    TempDir dir;
    const auto px = smooth_pixels(123, 45, 3, 3u);
    for (raster::Deflater deflater : {raster::Deflater::isal, raster::Deflater::libdeflate})
        for (int level = 0; level <= raster::max_level(deflater); ++level) {
            raster::PngEncoding e;
            e.deflater = deflater;
            e.level = level;
            expect_round_trip(dir.path / "l.png", 123, 45, 3, px, e,
                              (deflater == raster::Deflater::isal ? "ISA-L level " : "libdeflate level ") +
                                  std::to_string(level));
        }
}

// Incompressible pixels overflow igzip's compressed blocks; the stream must still be whole.
TEST(PngWriter, IncompressiblePicturesDecodeWithEveryDeflater) {
    TempDir dir;
    const auto px = random_pixels(300, 200, 4, 9u);
    for (raster::Deflater deflater : {raster::Deflater::isal, raster::Deflater::libdeflate}) {
        raster::PngEncoding e;
        e.deflater = deflater;
        e.filter = raster::PngFilter::none;
        expect_round_trip(dir.path / "r.png", 300, 200, 4, px, e, "random pixels");
    }
}

// Signature, IHDR fields, and the CRC of every chunk (checked with zlib, not the encoder's own).
TEST(PngWriter, ChunksAreWellFormed) {
    TempDir dir;
    const auto px = smooth_pixels(17, 5, 4, 1u);
    raster::write_png(dir.path / "c.png", "c.png", 17, 5, 4, px.data());
    std::ifstream in(dir.path / "c.png", std::ios::binary);
    const std::vector<unsigned char> b{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    ASSERT_GT(b.size(), 8u + 25u + 12u);
    EXPECT_EQ(std::vector<unsigned char>(b.begin(), b.begin() + 8),
              (std::vector<unsigned char>{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}));
    auto be = [&](std::size_t o) {
        return std::uint32_t(b[o]) << 24 | std::uint32_t(b[o + 1]) << 16 | std::uint32_t(b[o + 2]) << 8 | b[o + 3];
    };
    std::vector<std::string> types;
    for (std::size_t at = 8; at + 12 <= b.size();) {
        const std::uint32_t n = be(at);
        ASSERT_LE(at + 12 + n, b.size());
        types.emplace_back(reinterpret_cast<const char*>(&b[at + 4]), 4);
        EXPECT_EQ(crc32(0, &b[at + 4], n + 4), be(at + 8 + n)) << types.back();
        if (types.back() == "IHDR") {
            ASSERT_EQ(n, 13u);
            EXPECT_EQ(be(at + 8), 17u);
            EXPECT_EQ(be(at + 12), 5u);
            EXPECT_EQ(b[at + 16], 8);  // bit depth
            EXPECT_EQ(b[at + 17], 6);  // RGBA
            EXPECT_EQ(b[at + 18] | b[at + 19] | b[at + 20], 0);
        }
        at += 12 + n;
    }
    ASSERT_GE(types.size(), 3u);
    EXPECT_EQ(types.front(), "IHDR");
    EXPECT_EQ(types[1], "IDAT");
    EXPECT_EQ(types.back(), "IEND");
}

// The trial picks the filter from a sample of the rows; on pictures alike all over it must do
// as well as the best single filter (within 2%).
TEST(PngWriter, TrialDoesAsWellAsTheBestFilter) {
    TempDir dir;
    for (int channels : {1, 3}) {
        for (bool smooth : {false, true}) {
            const auto px = smooth ? smooth_pixels(400, 300, channels, 5u) : random_pixels(400, 300, channels, 5u);
            std::uintmax_t best = UINTMAX_MAX, trial = 0;
            for (raster::PngFilter f : kAllFilters) {
                raster::PngEncoding e;
                e.filter = f;
                raster::write_png(dir.path / "t.png", "t.png", 400, 300, channels, px.data(), e);
                const std::uintmax_t size = fs::file_size(dir.path / "t.png");
                if (f == raster::PngFilter::trial) trial = size;
                else best = std::min(best, size);
            }
            EXPECT_LE(double(trial), 1.02 * double(best)) << channels << (smooth ? " smooth" : " random");
        }
    }
}

TEST(PngWriter, BadArgumentsThrowNamingTheFile) {
    TempDir dir;
    const std::vector<std::uint8_t> px(16, 0);
    try {
        raster::write_png(dir.path / "x.png", "shown.png", 2, 2, 5, px.data());
        FAIL() << "5 channels accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("shown.png"), std::string::npos) << e.what();
    }
    raster::PngEncoding e;
    e.level = 4;  // ISA-L's levels are 0..3
    EXPECT_THROW(raster::write_png(dir.path / "x.png", "x.png", 2, 2, 1, px.data(), e), InputError);
    e.deflater = raster::Deflater::libdeflate;
    e.level = 13;
    EXPECT_THROW(raster::write_png(dir.path / "x.png", "x.png", 2, 2, 1, px.data(), e), InputError);
    EXPECT_THROW(raster::write_png(dir.path / "no_such_dir" / "x.png", "x.png", 2, 2, 1, px.data()), InputError);
}

// Grey + alpha (map tiles): libpng decodes the same pixels, and encode_png gives the bytes
// write_png writes, the same on every call.
TEST(PngWriter, GreyAlphaRoundTripsAndEncodeMatchesTheFile) {
    TempDir dir;
    const int w = 37, h = 23;
    std::vector<std::uint8_t> px(std::size_t(w) * h * 2);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const bool covered = (i + j) % 5 != 0;
            px[2 * (std::size_t(j) * w + i)] = covered ? std::uint8_t(i * 7 + j * 3) : 0;
            px[2 * (std::size_t(j) * w + i) + 1] = covered ? 255 : 0;
        }
    const auto file = dir.path / "ga.png";
    raster::write_png(file, file, w, h, 2, px.data());
    const test::DecodedPng decoded = test::decode_png_with_libpng(file);
    EXPECT_EQ(decoded.channels, 2);
    EXPECT_EQ(decoded.pixels, px);
    const auto bytes = raster::encode_png(w, h, 2, px.data());
    std::ifstream in(file, std::ios::binary);
    const std::vector<std::uint8_t> written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(bytes, written);
    EXPECT_EQ(raster::encode_png(w, h, 2, px.data()), bytes);
}

// A write that fails half-way (the file-size limit stands in for a full disk) is an InputError,
// and write_u8_image leaves neither the target nor its temporary file.
TEST(PngWriter, AFailedWriteLeavesNoFile) {
    TempDir dir;
    const auto px = random_pixels(200, 200, 3, 2u);  // ~120 KB, incompressible
    rlimit old{};
    ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
    const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);  // a short write instead of the signal
    rlimit small = old;
    small.rlim_cur = 4096;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
    bool threw = false;
    try {
        raster::write_u8_image(dir.path / "big.png", 200, 200, 3, px.data(), nullptr);
    } catch (const InputError&) {
        threw = true;
    }
    setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, old_handler);
    EXPECT_TRUE(threw);
    EXPECT_TRUE(fs::is_empty(dir.path));
}

}  // namespace
