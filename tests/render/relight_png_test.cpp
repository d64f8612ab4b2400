// Relit frames written as PNG (write_image through BackgroundWriter, as `relight` writes them)
// decode to the pixels terrashade's earlier libpng encoder gave for the same frames: the
// encoder changed, the pictures did not.
#include <filesystem>
#include <string>
#include <vector>
#include <unistd.h>

#include <gtest/gtest.h>

#include "core/dem/crop.hpp"
#include "core/dem/fill_voids.hpp"
#include "core/dem/read_dem.hpp"
#include "core/render/background_writer.hpp"
#include "core/render/render_scene.hpp"
#include "tests/raster/libpng_reference.hpp"

namespace ts::render {
namespace {

struct TempDir {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("ts_relight_png_" + std::to_string(::getpid()));
    TempDir() { std::filesystem::create_directories(path); }
    ~TempDir() { std::filesystem::remove_all(path); }
};

// 0.2 x 0.2 degrees around Grenoble (101 x 101 texels), as in the command-line tests.
dem::Dem grenoble_crop() {
    dem::Dem d = dem::crop(dem::read_dem(std::string(TS_SOURCE_DIR) + "/data/grenoble_500px.tif"),
                           {5.65, 45.10, 5.85, 45.30});
    dem::fill_voids(d);
    return d;
}

void expect_frames_match_libpng(const dem::Dem& dem, const SceneOptions& options, const std::string& what) {
    TempDir dir;
    Scene scene(dem, options);
    Exposure exposure;  // auto: each frame's own log-average, as `bench relight` writes them
    std::vector<LinearImage> frames;
    {
        BackgroundWriter writer(1, 3);
        LinearImage image;
        for (int k = 0; k < 4; ++k) {
            scene.render({90.0 + 50.0 * k, 6.0 + 15.0 * k}, image);
            frames.push_back(image);
            writer.write((dir.path / ("frame_" + std::to_string(k) + ".png")).string(), image, exposure, nullptr);
        }
        writer.finish();
    }
    for (int k = 0; k < 4; ++k) {
        const LinearImage& f = frames[std::size_t(k)];
        const auto bytes = tone_map_to_srgb8(f.rgb.data(), f.rgb.size(), image_exposure_scale(f, exposure));
        const auto reference = dir.path / ("libpng_" + std::to_string(k) + ".png");
        test::encode_png_with_libpng(reference, f.width, f.height, 3, bytes.data());
        const test::DecodedPng ours = test::decode_png_with_libpng(dir.path / ("frame_" + std::to_string(k) + ".png"));
        const test::DecodedPng theirs = test::decode_png_with_libpng(reference);
        EXPECT_EQ(ours.width, f.width) << what << k;
        EXPECT_EQ(ours.height, f.height) << what << k;
        EXPECT_EQ(ours.channels, 3) << what << k;
        EXPECT_EQ(ours.pixels, theirs.pixels) << what << " frame " << k;
        EXPECT_EQ(ours.pixels, bytes) << what << " frame " << k;
    }
}

TEST(RelightPng, MapFramesDecodeToTheLibpngEncodersPixels) {
    const dem::Dem dem = grenoble_crop();
    expect_frames_match_libpng(dem, SceneOptions{}, "map");
}

TEST(RelightPng, PerspectiveFramesDecodeToTheLibpngEncodersPixels) {
    const dem::Dem dem = grenoble_crop();
    SceneOptions options;
    options.view = ViewKind::perspective;
    options.perspective.width = 97;
    options.perspective.height = 41;
    expect_frames_match_libpng(dem, options, "perspective");
}

}  // namespace
}  // namespace ts::render
