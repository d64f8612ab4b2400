// A magnified map shades the sun per pixel (core/render/map_pixel_sun.hpp): at the texel centres
// it is the texels' own shading, and a cast shadow's edge is as sharp as the pixels, where the
// blend of the texels' shares ramps over a texel.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/dem/crop.hpp"
#include "core/dem/read_dem.hpp"
#include "core/geo/crs.hpp"
#include "core/render/map_pixel_sun.hpp"
#include "core/render/render_scene.hpp"

namespace ts::render {
namespace {

float luminance(const glm::vec3& c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

TEST(MapPixelSun, PixelsMagnifyWhenTheyAreSmallerThanTheTexels) {
    auto grid_of = [](int w, int h, float step) {
        std::vector<glm::vec2> at;
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) at.emplace_back(i * step, j * step);
        return at;
    };
    EXPECT_TRUE(pixels_magnify(grid_of(8, 8, 0.25f), 8, 8));
    EXPECT_FALSE(pixels_magnify(grid_of(8, 8, 1.0f), 8, 8));
    EXPECT_FALSE(pixels_magnify(grid_of(8, 8, 2.0f), 8, 8));
    std::vector<glm::vec2> off(64, glm::vec2(-1.0f));  // no pixel on the DEM
    EXPECT_FALSE(pixels_magnify(off, 8, 8));
}

TEST(MapPixelSun, AtTheTexelCentresAMagnifiedMapIsTheTexelsShading) {
    const dem::Dem dem =
        dem::crop(dem::read_dem(std::string(TS_SOURCE_DIR) + "/data/grenoble_500px.tif"), {5.65, 45.10, 5.85, 45.30});
    const int n = dem.width;
    ASSERT_EQ(dem.height, n);
    Scene native(dem, SceneOptions{});
    SceneOptions three;
    three.map_width = three.map_height = 3 * n;  // pixel 3c + 1 sits on texel c's centre
    Scene magnified(dem, three);
    for (const SunState sun : {SunState{135.0, 30.0}, SunState{250.0, 12.0}}) {
        LinearImage a, b;
        native.render(sun, a);
        magnified.render(sun, b);
        ASSERT_EQ(b.width, 3 * n);
        std::vector<double> diff;
        for (int r = 2; r < n - 2; ++r)
            for (int c = 2; c < n - 2; ++c) {
                const float la = luminance(a.rgb[std::size_t(r) * n + c]);
                const float lb = luminance(b.rgb[std::size_t(3 * r + 1) * (3 * n) + std::size_t(3 * c + 1)]);
                diff.push_back(std::abs(lb - la) / la);
            }
        std::sort(diff.begin(), diff.end());
        // Where the four texels agree on the sun the pixel is the texel; where a shadow's edge
        // crosses them the pixel's own ray decides, as the sweep did for the texel.
        EXPECT_LT(diff[diff.size() / 2], 1e-4) << sun.elevation_deg;
        EXPECT_LT(diff[diff.size() * 95 / 100], 0.02) << sun.elevation_deg;
    }
}

// A 60 m wall (a plateau's west face) on flat ground under a sun in the east, 20 degrees up:
// its shadow's edge runs north-south 165 m (5.5 texels) west of it.
dem::Dem wall() {
    dem::Dem d;
    d.width = d.height = 48;
    d.z.assign(std::size_t(48 * 48), 500.0f);  // above the sea, which would be water
    d.void_mask.assign(d.z.size(), 0);
    for (int r = 0; r < 48; ++r)
        for (int c = 20; c < 28; ++c) d.z[std::size_t(r) * 48 + c] = 560.0f;
    d.georef = geo::Georef(48, 48, {500000.0, 30.0, 0.0, 5000000.0, 0.0, -30.0}, geo::Crs::from_epsg(32631), true);
    return d;
}

// The share of the fall from lit ground (texel column 12) into the shadow (column 17) along row
// `row` that happens within 3 pixels. (The shadow darkens towards the wall, as the wall hides
// more of the sky: a fixed threshold would count that as edge.)
double edge_share(const LinearImage& image, int scale, int row) {
    auto at = [&](int i) { return double(luminance(image.rgb[std::size_t(row) * image.width + std::size_t(i)])); };
    const int i0 = 12 * scale, i1 = 17 * scale;
    double steepest = 0;
    for (int i = i0; i + 3 <= i1; ++i) steepest = std::max(steepest, at(i) - at(i + 3));
    return steepest / (at(i0) - at(i1));
}

TEST(MapPixelSun, ACastShadowsEdgeIsAsSharpAsThePixels) {
    const dem::Dem dem = wall();
    const int scale = 8;
    SceneOptions options;
    options.map_width = options.map_height = 48 * scale;
    Scene per_pixel(dem, options);
    options.perspective.pixel_sun_shadows = false;  // --shadow-detail texel: the texels' shares blended
    Scene blended(dem, options);
    LinearImage a, b;
    per_pixel.render({90.0, 20.0}, a);
    blended.render({90.0, 20.0}, b);
    const int row = 24 * scale + scale / 2;
    // The sun's disc (0.53 degrees) widens the edge by 1.5 m at 165 m: a pixel here is 3.75 m.
    // Measured: 0.82 per pixel, 0.32 blended (a texel's ramp of 8 pixels).
    EXPECT_GT(edge_share(a, scale, row), 0.75);
    EXPECT_LT(edge_share(b, scale, row), 0.45);
}

}  // namespace
}  // namespace ts::render
