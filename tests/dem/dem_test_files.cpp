#include "tests/dem/dem_test_files.hpp"

#include <fstream>
#include <stdexcept>

#include <geotiff.h>
#include <geovalues.h>
#include <xtiffio.h>
#include <zip.h>

#include "core/raster/tiff_file.hpp"

namespace ts::dem::test_files {

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

void write_zip(const std::filesystem::path& path, const std::string& entry, const std::string& content) {
    int err = 0;
    zip_t* z = zip_open(path.string().c_str(), ZIP_CREATE | ZIP_TRUNCATE, &err);
    zip_source_t* src = zip_source_buffer(z, content.data(), content.size(), 0);
    zip_file_add(z, entry.c_str(), src, ZIP_FL_OVERWRITE);
    zip_close(z);
}

int sparse_blocks(const std::filesystem::path& path) {
    ts::raster::TiffFile file(path, "r");
    TIFF* tif = file.get();
    const std::uint32_t n = TIFFIsTiled(tif) ? TIFFNumberOfTiles(tif) : TIFFNumberOfStrips(tif);
    int sparse = 0;
    for (std::uint32_t i = 0; i < n; ++i) sparse += TIFFGetStrileByteCount(tif, i) == 0;
    return sparse;
}

std::string synthetic_hgt(const std::vector<std::pair<int, int>>& voids) {
    const int n = 1201;
    std::string bytes(std::size_t(n) * n * 2, '\0');
    auto put = [&](int c, int r, std::int16_t v) {
        const std::size_t i = (std::size_t(r) * n + std::size_t(c)) * 2;
        bytes[i] = char((std::uint16_t(v) >> 8) & 0xff);
        bytes[i + 1] = char(std::uint16_t(v) & 0xff);
    };
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) put(c, r, std::int16_t(c + r));
    for (auto [c, r] : voids) put(c, r, -32768);
    return bytes;
}

void write_tiff(const std::filesystem::path& path, const TiffSpec& s, const std::vector<std::uint8_t>& samples) {
    raster::register_tiff_tags();
    TIFF* tif = XTIFFOpen(path.string().c_str(), "w");
    if (!tif) throw std::runtime_error("cannot write " + path.string());
    TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, std::uint32_t(s.width));
    TIFFSetField(tif, TIFFTAG_IMAGELENGTH, std::uint32_t(s.height));
    TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, s.bits);
    TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, s.sample_format);
    TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, s.spp);
    TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, s.spp == 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK);
    const std::size_t pixel_bytes = std::size_t(s.spp) * std::size_t(s.bits / 8);
    if (!s.nodata.empty()) TIFFSetField(tif, TIFFTAG_GDAL_NODATA, s.nodata.c_str());
    if (!s.copyright.empty()) TIFFSetField(tif, TIFFTAG_COPYRIGHT, s.copyright.c_str());
    if (s.epsg >= 0) {
        double tie[6] = {0, 0, 0, s.x0, s.y0, 0};
        double scale[3] = {s.cell, s.cell, 0};
        TIFFSetField(tif, TIFFTAG_GEOTIEPOINTS, 6, tie);
        TIFFSetField(tif, TIFFTAG_GEOPIXELSCALE, 3, scale);
        GTIF* gt = GTIFNew(tif);
        GTIFKeySet(gt, GTModelTypeGeoKey, TYPE_SHORT, 1, s.geographic ? ModelTypeGeographic : ModelTypeProjected);
        GTIFKeySet(gt, GTRasterTypeGeoKey, TYPE_SHORT, 1, s.pixel_is_point ? RasterPixelIsPoint : RasterPixelIsArea);
        if (s.epsg > 0)
            GTIFKeySet(gt, s.geographic ? GeographicTypeGeoKey : ProjectedCSTypeGeoKey, TYPE_SHORT, 1, s.epsg);
        GTIFWriteKeys(gt);
        GTIFFree(gt);
    }
    if (s.tiled) {
        const int tile = 16;
        TIFFSetField(tif, TIFFTAG_TILEWIDTH, tile);
        TIFFSetField(tif, TIFFTAG_TILELENGTH, tile);
        std::vector<std::uint8_t> block(std::size_t(tile * tile) * pixel_bytes);
        for (int ty = 0; ty < s.height; ty += tile)
            for (int tx = 0; tx < s.width; tx += tile) {
                std::fill(block.begin(), block.end(), 0);
                for (int r = 0; r < tile && ty + r < s.height; ++r)
                    for (int c = 0; c < tile && tx + c < s.width; ++c)
                        std::memcpy(&block[(std::size_t(r) * tile + std::size_t(c)) * pixel_bytes],
                                    &samples[(std::size_t(ty + r) * std::size_t(s.width) + std::size_t(tx + c)) * pixel_bytes],
                                    pixel_bytes);
                TIFFWriteTile(tif, block.data(), std::uint32_t(tx), std::uint32_t(ty), 0, 0);
            }
    } else {
        TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, std::uint32_t(2));  // several strips, the last one short
        const std::size_t row_bytes = std::size_t(s.width) * pixel_bytes;
        for (int r = 0; r < s.height; ++r)
            TIFFWriteScanline(tif, const_cast<std::uint8_t*>(&samples[std::size_t(r) * row_bytes]), std::uint32_t(r), 0);
    }
    XTIFFClose(tif);
}

void write_lying_tiff(const std::filesystem::path& path, int width, int height, int compression, int tile,
                      const std::string& payload) {
    raster::register_tiff_tags();
    TIFF* tif = XTIFFOpen(path.string().c_str(), "w");
    if (!tif) throw std::runtime_error("cannot write " + path.string());
    TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, std::uint32_t(width));
    TIFFSetField(tif, TIFFTAG_IMAGELENGTH, std::uint32_t(height));
    TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, 16);
    TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_INT);
    TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, 1);
    TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
    TIFFSetField(tif, TIFFTAG_COMPRESSION, compression);
    double tie[6] = {0, 0, 0, 10, 1, 0};
    double scale[3] = {1.0 / 3600, 1.0 / 3600, 0};
    TIFFSetField(tif, TIFFTAG_GEOTIEPOINTS, 6, tie);
    TIFFSetField(tif, TIFFTAG_GEOPIXELSCALE, 3, scale);
    GTIF* gt = GTIFNew(tif);
    GTIFKeySet(gt, GTModelTypeGeoKey, TYPE_SHORT, 1, ModelTypeGeographic);
    GTIFKeySet(gt, GeographicTypeGeoKey, TYPE_SHORT, 1, 4326);
    GTIFWriteKeys(gt);
    GTIFFree(gt);
    auto* data = reinterpret_cast<std::uint8_t*>(const_cast<char*>(payload.data()));
    if (tile > 0) {
        TIFFSetField(tif, TIFFTAG_TILEWIDTH, std::uint32_t(tile));
        TIFFSetField(tif, TIFFTAG_TILELENGTH, std::uint32_t(tile));
        const std::uint32_t n = TIFFNumberOfTiles(tif);
        for (std::uint32_t i = 0; i < n; ++i) TIFFWriteRawTile(tif, i, data, tmsize_t(payload.size()));
    } else {
        TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, std::uint32_t(height));
        TIFFWriteRawStrip(tif, 0, data, tmsize_t(payload.size()));
    }
    XTIFFClose(tif);
}

}  // namespace ts::dem::test_files
