// The one registry of output formats: each extension finds its writer whatever its case, the
// lists the commands give their IoPlan come from it in the order users read, and an extension
// no writer has finds nothing.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/raster/image_writer_registry.hpp"

namespace ts::raster {
namespace {

using Strings = std::vector<std::string>;

TEST(ImageWriterRegistry, FindsEachWriterByExtensionInAnyCase) {
    EXPECT_TRUE(written_as("out/a.png", ImageWriter::png));
    EXPECT_TRUE(written_as("A.PNG", ImageWriter::png));
    EXPECT_TRUE(written_as("map.tif", ImageWriter::geotiff));
    EXPECT_TRUE(written_as("map.TIFF", ImageWriter::geotiff));
    EXPECT_TRUE(written_as("hdr.exr", ImageWriter::exr));
    EXPECT_TRUE(written_as("set.mbtiles", ImageWriter::mbtiles));
    EXPECT_FALSE(written_as("set.mbtiles", ImageWriter::png));
    EXPECT_EQ(find_image_format("x.jpg"), nullptr);
    EXPECT_EQ(find_image_format("folder/"), nullptr);
    EXPECT_EQ(find_image_format("png"), nullptr);  // a name, not an extension
}

TEST(ImageWriterRegistry, CapabilitiesSayWhatAFileCanHold) {
    const ImageFormat& png = *find_image_format("a.png");
    EXPECT_FALSE(png.georeferenced);
    EXPECT_TRUE(png.u8 && png.alpha && !png.float32 && !png.multi_band);
    const ImageFormat& tif = *find_image_format("a.tif");
    EXPECT_TRUE(tif.georeferenced && tif.u8 && tif.float32 && tif.multi_band);
    const ImageFormat& exr = *find_image_format("a.exr");
    EXPECT_TRUE(exr.float32 && !exr.u8 && !exr.georeferenced);
    EXPECT_TRUE(find_image_format("a.mbtiles")->tile_set);
}

TEST(ImageWriterRegistry, CommandListsComeFromTheRegistry) {
    EXPECT_EQ(picture_extensions(), (Strings{".png", ".tif", ".tiff", ".exr"}));
    EXPECT_EQ(u8_picture_extensions(), (Strings{".png", ".tif", ".tiff"}));
    EXPECT_EQ(float_raster_extensions(), (Strings{".tif", ".tiff"}));
    EXPECT_EQ(tile_set_extensions(), (Strings{".mbtiles"}));
    EXPECT_EQ(image_extensions([](const ImageFormat& f) { return f.alpha; }).size(), image_formats().size());
}

}  // namespace
}  // namespace ts::raster
