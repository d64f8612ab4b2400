// Texels outside the terrain (a nodata collar left NaN by fill_voids) in a rendered map: they are
// transparent, the terrain keeps a finite colour, and the automatic exposure sees only terrain.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/dem/crop.hpp"
#include "core/dem/fill_voids.hpp"
#include "core/dem/read_dem.hpp"
#include "core/render/render_scene.hpp"
#include "core/render/tone_map.hpp"

namespace ts::render {
namespace {

// 101 x 101 texels around Grenoble; with a collar, the texels with c + r < 40 are nodata (as in a
// corner of a gdalwarp copy).
dem::Dem grenoble_crop(bool collar) {
    dem::Dem d = dem::crop(dem::read_dem(std::string(TS_SOURCE_DIR) + "/data/grenoble_500px.tif"),
                           {5.65, 45.10, 5.85, 45.30});
    if (collar)
        for (int r = 0; r < d.height; ++r)
            for (int c = 0; c < d.width; ++c)
                if (c + r < 40) d.z[d.index(c, r)] = NAN, d.void_mask[d.index(c, r)] = 1;
    dem::fill_voids(d);
    return d;
}

TEST(OutsideTerrain, TheCollarIsTransparentAndTheTerrainIsShaded) {
    const dem::Dem dem = grenoble_crop(true);
    Scene scene(dem, SceneOptions{});
    LinearImage image;
    scene.render({135.0, 30.0}, image);
    ASSERT_EQ(image.alpha.size(), image.rgb.size());
    for (int r = 0; r < image.height; ++r)
        for (int c = 0; c < image.width; ++c) {
            const std::size_t k = std::size_t(r) * std::size_t(image.width) + std::size_t(c);
            if (c + r < 40) {
                ASSERT_EQ(image.alpha[k], 0) << c << "," << r;
            } else {
                ASSERT_EQ(image.alpha[k], 255) << c << "," << r;
                ASSERT_TRUE(std::isfinite(image.rgb[k].x) && image.rgb[k].x > 0) << c << "," << r;
            }
        }
}

TEST(OutsideTerrain, AutomaticExposureIgnoresTheCollar) {
    const dem::Dem dem = grenoble_crop(true);
    Scene scene(dem, SceneOptions{});
    LinearImage image;
    scene.render({135.0, 30.0}, image);
    std::vector<glm::vec3> terrain;
    for (std::size_t k = 0; k < image.rgb.size(); ++k)
        if (image.alpha[k]) terrain.push_back(image.rgb[k]);
    const Exposure automatic;
    const double want = exposure_scale(automatic, log_average_luminance(terrain.data(), terrain.size()));
    EXPECT_DOUBLE_EQ(image_exposure_scale(image, automatic), want);
    // Whatever colour the collar held, the exposure would not move: only terrain counts.
    for (std::size_t k = 0; k < image.rgb.size(); ++k)
        if (!image.alpha[k]) image.rgb[k] = glm::vec3(1e6f);
    EXPECT_DOUBLE_EQ(image_exposure_scale(image, automatic), want);
    image.alpha.clear();  // counted as terrain, the bright collar would darken the picture
    EXPECT_LT(image_exposure_scale(image, automatic), 0.5 * want);
}

TEST(OutsideTerrain, AResampledMapIsTransparentOverTheCollarToo) {
    const dem::Dem dem = grenoble_crop(true);
    SceneOptions options;
    options.map_width = options.map_height = 50;
    Scene scene(dem, options);
    LinearImage image;
    scene.render({135.0, 30.0}, image);
    ASSERT_EQ(image.width, 50);
    ASSERT_EQ(image.alpha.size(), image.rgb.size());
    EXPECT_EQ(image.alpha[0], 0);                                 // the corner: collar
    EXPECT_EQ(image.alpha[std::size_t(25 * 50 + 25)], 255);       // the middle: terrain
    EXPECT_EQ(image.alpha[std::size_t(49 * 50 + 49)], 255);
    for (std::size_t k = 0; k < image.rgb.size(); ++k) {
        if (image.alpha[k]) {
            ASSERT_TRUE(std::isfinite(image.rgb[k].x)) << k;
        }
    }
}

TEST(OutsideTerrain, WithoutVoidsAMapHasNoAlphaChannel) {
    const dem::Dem dem = grenoble_crop(false);
    Scene scene(dem, SceneOptions{});
    LinearImage image;
    scene.render({135.0, 30.0}, image);
    EXPECT_TRUE(image.alpha.empty());
}

}  // namespace
}  // namespace ts::render
