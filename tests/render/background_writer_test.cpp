// BackgroundWriter: the files it writes are the bytes write_image writes, in any number of
// frames through a short queue; a failed write surfaces as the next call's error.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>

#include <gtest/gtest.h>

#include "core/render/background_writer.hpp"
#include "core/util/error.hpp"

namespace ts::render {
namespace {

std::string read_bytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

LinearImage gradient(int w, int h, float k) {
    LinearImage im{w, h, {}};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) im.rgb.emplace_back(k * x / w, k * y / h, k * 0.5f);
    return im;
}

struct TempDir {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("ts_background_writer_" + std::to_string(::getpid()));
    TempDir() { std::filesystem::create_directories(path); }
    ~TempDir() { std::filesystem::remove_all(path); }
};

TEST(BackgroundWriter, WritesWhatWriteImageWrites) {
    TempDir dir;
    Exposure e;
    e.automatic = false;
    e.ev100 = 10.0;
    const int frames = 7;
    {
        BackgroundWriter writer(2);
        LinearImage image;
        for (int k = 0; k < frames; ++k) {
            image = gradient(33, 21, 0.5f + k);  // into whatever storage the writer handed back
            writer.write((dir.path / ("bg_" + std::to_string(k) + ".png")).string(), image, e, nullptr);
        }
        writer.finish();
    }
    for (int k = 0; k < frames; ++k) {
        const auto ref = dir.path / ("ref_" + std::to_string(k) + ".png");
        write_image(ref.string(), gradient(33, 21, 0.5f + k), e, nullptr);
        const std::string got = read_bytes(dir.path / ("bg_" + std::to_string(k) + ".png"));
        EXPECT_FALSE(got.empty()) << k;
        EXPECT_EQ(got, read_bytes(ref)) << k;
    }
    // Only the frames: no temporary file left behind.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path), std::filesystem::directory_iterator()),
              2 * frames);
}

TEST(BackgroundWriter, AFailedWriteIsReported) {
    TempDir dir;
    BackgroundWriter writer(1);
    LinearImage image = gradient(8, 8, 1.0f);
    writer.write((dir.path / "no_such_dir" / "a.png").string(), image, Exposure{}, nullptr);
    // Reported by finish() (or by a later write(), whichever comes first after the failure).
    EXPECT_THROW(
        {
            LinearImage next = gradient(8, 8, 1.0f);
            writer.write((dir.path / "b.png").string(), next, Exposure{}, nullptr);
            writer.finish();
        },
        InputError);
}

TEST(BackgroundWriter, DestructorWaitsForQueuedFrames) {
    TempDir dir;
    {
        BackgroundWriter writer(3);
        for (int k = 0; k < 3; ++k) {
            LinearImage image = gradient(16, 16, 1.0f + k);
            writer.write((dir.path / ("f" + std::to_string(k) + ".png")).string(), image, Exposure{}, nullptr);
        }
    }
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::filesystem::exists(dir.path / ("f" + std::to_string(k) + ".png")));
}

}  // namespace
}  // namespace ts::render
