// BackgroundWriter: the files it writes are the bytes write_image writes, in any number of
// frames through a short queue and on one or several threads; a failed write surfaces as the
// next call's error and leaves no temporary file.
#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
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

LinearImage noise(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 2.0f);
    LinearImage im{w, h, {}};
    for (int i = 0; i < w * h; ++i) im.rgb.emplace_back(u(rng), u(rng), u(rng));
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

// Files whose name starts with '.': write_atomically's temporaries (".name.tmp-...").
int hidden_files(const std::filesystem::path& dir) {
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) n += e.path().filename().string()[0] == '.';
    return n;
}

TEST(BackgroundWriter, SeveralThreadsWriteEveryFrame) {
    TempDir dir;
    Exposure e;
    e.automatic = false;
    e.ev100 = 10.0;
    const int frames = 25;
    {
        BackgroundWriter writer(2, 3);
        LinearImage image;
        for (int k = 0; k < frames; ++k) {
            image = gradient(41 + k % 3, 19, 0.25f + 0.3f * k);
            writer.write((dir.path / ("bg_" + std::to_string(k) + ".png")).string(), image, e, nullptr);
        }
        writer.finish();
    }
    for (int k = 0; k < frames; ++k) {
        const auto ref = dir.path / ("ref_" + std::to_string(k) + ".png");
        write_image(ref.string(), gradient(41 + k % 3, 19, 0.25f + 0.3f * k), e, nullptr);
        const std::string got = read_bytes(dir.path / ("bg_" + std::to_string(k) + ".png"));
        EXPECT_FALSE(got.empty()) << k;
        EXPECT_EQ(got, read_bytes(ref)) << k;
    }
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path), std::filesystem::directory_iterator()),
              2 * frames);
}

TEST(BackgroundWriter, SeveralThreadsReportAFailedWrite) {
    TempDir dir;
    std::filesystem::create_directories(dir.path / "frame_4.png");  // a directory: that write fails
    bool threw = false;
    try {
        BackgroundWriter writer(2, 3);
        for (int k = 0; k < 10; ++k) {
            LinearImage image = gradient(64, 64, 1.0f + k);
            writer.write((dir.path / ("frame_" + std::to_string(k) + ".png")).string(), image, Exposure{}, nullptr);
        }
        writer.finish();
    } catch (const InputError& e) {
        threw = true;
        EXPECT_NE(std::string(e.what()).find("frame_4.png"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(threw);
    EXPECT_EQ(hidden_files(dir.path), 0);
    for (int k = 0; k < 4; ++k) {  // queued before the failing one: written or not, never half
        const auto f = dir.path / ("frame_" + std::to_string(k) + ".png");
        if (std::filesystem::exists(f)) {
            EXPECT_GT(std::filesystem::file_size(f), 0u);
        }
    }
}

// Writes that fail half-way on every thread (the file-size limit stands in for a full disk):
// the error is reported and no temporary file stays behind.
TEST(BackgroundWriter, FailuresHalfWayLeaveNoTemporaryFile) {
    TempDir dir;
    rlimit old{};
    ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
    const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);  // a short write instead of the signal
    rlimit small = old;
    small.rlim_cur = 2048;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
    bool threw = false;
    try {
        BackgroundWriter writer(2, 2);
        for (int k = 0; k < 6; ++k) {
            LinearImage image = noise(300, 200, unsigned(k));  // a PNG of ~180 KB
            writer.write((dir.path / ("f" + std::to_string(k) + ".png")).string(), image, Exposure{}, nullptr);
        }
        writer.finish();
    } catch (const InputError&) {
        threw = true;
    }
    setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, old_handler);
    EXPECT_TRUE(threw);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path));
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
