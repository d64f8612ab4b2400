// HDR maps: the lazily loaded image module (read .hdr/.exr, write .exr atomically), and the
// equirectangular orientation and bilinear lookup of HdrSky.
#include "core/light/hdr_sky.hpp"
#include "core/util/angles.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "core/geo/azimuth.hpp"
#include "core/light/sky.hpp"
#include "core/light/sky_sh.hpp"
#include "core/raster/image_io_plugin/float_image_io.hpp"
#include "core/sh/sh_basis.hpp"
#include "core/util/error.hpp"

namespace ts::light {
namespace {
namespace fs = std::filesystem;

fs::path scratch_dir() {
    const fs::path dir = fs::temp_directory_path() / ("ts_hdr_sky_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

// A Radiance RGBE file in the flat (uncompressed) scanline format, written here so the test
// needs no committed image.
void write_rgbe(const fs::path& path, int width, int height, const std::vector<float>& rgb) {
    std::ofstream out(path, std::ios::binary);
    out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << height << " +X " << width << "\n";
    for (int p = 0; p < width * height; ++p) {
        const float* c = &rgb[static_cast<std::size_t>(p) * 3];
        const float v = std::max({c[0], c[1], c[2]});
        unsigned char e[4] = {0, 0, 0, 0};
        if (v > 1e-32f) {
            int exponent = 0;
            const float scale = std::frexp(v, &exponent) * 256.0f / v;
            for (int k = 0; k < 3; ++k) e[k] = static_cast<unsigned char>(c[k] * scale);
            e[3] = static_cast<unsigned char>(exponent + 128);
        }
        out.write(reinterpret_cast<const char*>(e), 4);
    }
}

TEST(ImageModule, ReadsRgbeWrittenByHand) {
    const fs::path dir = scratch_dir();
    const int w = 9;
    const int h = 3;
    std::vector<float> rgb(static_cast<std::size_t>(w * h * 3));
    for (int p = 0; p < w * h; ++p) {
        rgb[p * 3 + 0] = 0.25f * static_cast<float>(p + 1);
        rgb[p * 3 + 1] = 1.0f;
        rgb[p * 3 + 2] = 100.0f * (p % 2);
    }
    write_rgbe(dir / "t.hdr", w, h, rgb);
    const raster::FloatImage image = raster::read_float_image(dir / "t.hdr");
    ASSERT_EQ(image.width, w);
    ASSERT_EQ(image.height, h);
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        // RGBE keeps 8 mantissa bits of the brightest channel: error <= max channel / 128.
        const std::size_t p = i / 3;
        const float brightest = std::max({rgb[p * 3], rgb[p * 3 + 1], rgb[p * 3 + 2]});
        EXPECT_NEAR(image.rgb[i], rgb[i], brightest / 128.0f) << i;
    }
    fs::remove_all(dir);
}

TEST(ImageModule, ExrRoundTripIsExactInFullFloatAndAtomic) {
    const fs::path dir = scratch_dir();
    const std::vector<float> rgba = {0.0f, 1.5f, 1e5f, 1.0f, 3.25f, 1e-4f, 2.0f, 0.5f, -1.0f, 0.125f, 7.0f, 0.0f};
    raster::write_float_image_exr(dir / "out.exr", 3, 1, 4, rgba.data(), /*full_float=*/true);
    int files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 1);  // no temporary left behind
    const raster::FloatImage back = raster::read_float_image(dir / "out.exr");
    ASSERT_EQ(back.width, 3);
    ASSERT_EQ(back.height, 1);
    for (int p = 0; p < 3; ++p) {
        for (int c = 0; c < 3; ++c) EXPECT_EQ(back.rgb[p * 3 + c], rgba[p * 4 + c]) << p << " " << c;
    }
    // Half floats: 11 significant bits, relative error <= 2^-11.
    const std::vector<float> rgb = {0.1f, 2.0f, 300.0f};
    raster::write_float_image_exr(dir / "half.exr", 1, 1, 3, rgb.data());
    const raster::FloatImage half = raster::read_float_image(dir / "half.exr");
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(half.rgb[c], rgb[c], rgb[c] / 2048.0f);
    fs::remove_all(dir);
}

TEST(ImageModule, MissingOrBadFilesAreOneLineInputErrors) {
    const fs::path dir = scratch_dir();
    try {
        raster::read_float_image(dir / "missing.exr");
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), (dir / "missing.exr").string() + ": no such file");
    }
    std::ofstream(dir / "junk.hdr") << "not an image\n";
    try {
        raster::read_float_image(dir / "junk.hdr");
        ADD_FAILURE();
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind((dir / "junk.hdr").string() + ": cannot read image", 0), 0u) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    EXPECT_THROW(raster::write_float_image_exr(dir / "nodir" / "x.exr", 1, 1, 1, std::vector<float>{1.0f}.data()),
                 InputError);
    EXPECT_THROW(make_sky(parse_sky_options((dir / "missing.hdr").string()), {0, 0, 1}), InputError);
    fs::remove_all(dir);
}

glm::dvec3 dir_from(double azimuth_deg, double elevation_deg) {
    return geo::enu_direction(geo::azimuth_cw_from_north_to_phi(azimuth_deg), radians(elevation_deg));
}

raster::FloatImage indexed_map(int w, int h) {
    raster::FloatImage image{w, h, std::vector<float>(static_cast<std::size_t>(w * h * 3))};
    for (int row = 0; row < h; ++row) {
        for (int col = 0; col < w; ++col) {
            float* p = &image.rgb[(static_cast<std::size_t>(row) * w + col) * 3];
            p[0] = static_cast<float>(col);
            p[1] = static_cast<float>(row);
            p[2] = 1.0f;
        }
    }
    return image;
}

TEST(HdrSky, OrientationAndBilinearLookup) {
    const int w = 8;
    const int h = 4;
    // Pixel centre (col, row) is at azimuth rotation + ((col + 0.5)/w - 0.5) 360, elevation
    // 90 - (row + 0.5)/h 180.
    for (double rotation : {0.0, 90.0, -30.0}) {
        const HdrSky sky(indexed_map(w, h), "test", rotation, 2.0, {0, 0, 1});
        for (int row = 0; row < h; ++row) {
            for (int col = 0; col < w; ++col) {
                const double az = rotation + ((col + 0.5) / w - 0.5) * 360.0;
                const double el = 90.0 - (row + 0.5) / h * 180.0;
                const Rgb l = sky.radiance(dir_from(az, el));
                EXPECT_NEAR(l.r, 2.0 * col, 1e-5) << rotation << " " << col << " " << row;
                EXPECT_NEAR(l.g, 2.0 * row, 1e-5) << rotation << " " << col << " " << row;
            }
        }
    }
    // Default: the centre column faces north, east is to its right (columns 4..5 of 8).
    const HdrSky sky(indexed_map(w, h), "test", 0.0, 1.0, {0, 0, 1});
    EXPECT_NEAR(sky.radiance(dir_from(0.0, 22.5)).r, 3.5f, 1e-5);   // between columns 3 and 4
    EXPECT_NEAR(sky.radiance(dir_from(90.0, 22.5)).r, 5.5f, 1e-5);  // east: u = 0.75
    // Wrap: halfway between the last and the first column (due south) blends them.
    EXPECT_NEAR(sky.radiance(dir_from(180.0, 22.5)).r, 0.5f * (7.0f + 0.0f), 1e-5);
    // Clamped at the poles.
    EXPECT_NEAR(sky.radiance({0.0, 0.0, 1.0}).g, 0.0f, 1e-6);
    EXPECT_NEAR(sky.radiance({0.0, 0.0, -1.0}).g, 3.0f, 1e-6);
    EXPECT_EQ(sky.sun().irradiance, Rgb(0.0f));
}

TEST(HdrSky, ConstantMapProjectsToDcOnly) {
    raster::FloatImage image{64, 32, std::vector<float>(64 * 32 * 3, 0.75f)};
    const HdrSky sky(std::move(image), "flat", 0.0, 2.0, {0, 0, 1});
    const SkySh s = project_sky_sh(sky);
    EXPECT_NEAR(s[0].r, 1.5 * sh::kSqrt4Pi, 1e-5);
    for (int i = 1; i < sh::kCount; ++i) EXPECT_NEAR(s[i].r, 0.0, 1e-5) << i;
}

TEST(HdrSky, MakeSkyReadsTheMapThroughTheModule) {
    const fs::path dir = scratch_dir();
    const std::vector<float> rgb(16 * 8 * 3, 0.5f);
    write_rgbe(dir / "flat.hdr", 16, 8, rgb);
    const auto sky = make_sky(parse_sky_options((dir / "flat.hdr").string() + ",scale=4"), {0, 0, 1});
    EXPECT_NEAR(sky->radiance(dir_from(123.0, 45.0)).g, 2.0f, 1e-6);
    EXPECT_NE(sky->describe().find("16x8"), std::string::npos);
    fs::remove_all(dir);
}

TEST(HdrSky, ShippedSyntheticSunsetHasItsSunInTheWest) {
    // data/sunset_synthetic.hdr (scripts/make_synthetic_sky_hdr.py): sun 4 deg up at azimuth 265.
    const auto sky = make_sky(parse_sky_options(std::string(TS_SOURCE_DIR) + "/data/sunset_synthetic.hdr"), {0, 0, 1});
    const auto* hdr = dynamic_cast<const HdrSky*>(sky.get());
    ASSERT_NE(hdr, nullptr);
    const glm::dvec3 d = hdr->brightest_direction();
    // One pixel is 1.4 deg: the brightest pixel centre is within 1.5 deg of the blob's centre.
    const double az = geo::phi_to_azimuth_cw_from_north(std::atan2(d.y, d.x));
    const double el = degrees(std::asin(d.z));
    EXPECT_NEAR(az, 265.0, 1.5);
    EXPECT_NEAR(el, 4.0, 1.5);
    // Rotating the map by 90 deg moves the sun to azimuth 355.
    const auto turned =
        make_sky(parse_sky_options(std::string(TS_SOURCE_DIR) + "/data/sunset_synthetic.hdr,rotation=90"), {0, 0, 1});
    const glm::dvec3 t = dynamic_cast<const HdrSky*>(turned.get())->brightest_direction();
    EXPECT_NEAR(geo::phi_to_azimuth_cw_from_north(std::atan2(t.y, t.x)), 355.0, 1.5);
    // Its SH: the linear band points west (towards the sun and the bright sky around it).
    const SkySh s = project_sky_sh(*sky);
    EXPECT_GT(s[0].r, 0.0f);
    // Y_{1,1} ~ x (east): negative for a western sun.
    EXPECT_LT(s[sh::index(1, 1)].r, 0.0f);
}

}  // namespace
}  // namespace ts::light
