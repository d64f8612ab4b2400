#include "core/raster/raster_writer.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <memory>

#include "core/raster/gdal_band_metadata.hpp"
#include "core/raster/geotiff_georef.hpp"
#include "core/raster/image_writer_registry.hpp"
#include "core/raster/png_writer.hpp"
#include "core/raster/tiff_file.hpp"
#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"

namespace ts::raster {

namespace {

void check_size(const std::filesystem::path& path, int width, int height, int planes) {
    if (width <= 0 || height <= 0 || planes <= 0)
        throw input_error(path.string(), "cannot write an empty raster (" + std::to_string(width) + "x" +
                                             std::to_string(height) + "x" + std::to_string(planes) + ")");
}

// Rows per strip for ~256 KiB strips: few enough strips to write fast, small enough to stream.
std::uint32_t rows_per_strip(std::size_t row_bytes) {
    return std::uint32_t(std::max<std::size_t>(1, (256 * 1024) / std::max<std::size_t>(1, row_bytes)));
}

const char* tiff_mode(std::size_t bytes) {
    return bytes > (std::size_t(3) << 30) ? "w8" : "w";  // BigTIFF beyond ~3 GiB
}

void write_strips(TiffFile& file, int height, int planes_separate, std::size_t row_bytes, const std::uint8_t* data) {
    TIFF* tif = file.get();
    const std::uint32_t rps = rows_per_strip(row_bytes);
    TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, rps);
    tstrip_t strip = 0;
    for (int plane = 0; plane < planes_separate; ++plane) {
        const std::uint8_t* base = data + std::size_t(plane) * row_bytes * std::size_t(height);
        for (int row = 0; row < height; row += int(rps), ++strip) {
            const int rows = std::min<int>(int(rps), height - row);
            if (TIFFWriteEncodedStrip(tif, strip, const_cast<std::uint8_t*>(base + std::size_t(row) * row_bytes),
                                      tmsize_t(row_bytes * std::size_t(rows))) < 0)
                throw input_error(file.path(), "writing TIFF failed: " + file.last_error());
        }
    }
}

}  // namespace

void write_float_raster(const std::filesystem::path& path, int width, int height, int bands, const float* data,
                        const geo::Georef& georef, const std::vector<std::string>& band_names) {
    if (!written_as(path, ImageWriter::geotiff))
        throw input_error(path.string(), "unknown extension for a float raster (use .tif or .tiff)");
    check_size(path, width, height, bands);
    if (!georef.valid()) throw input_error(path.string(), "float raster without georeferencing");
    const std::size_t row_bytes = std::size_t(width) * sizeof(float);
    write_atomically(path, [&](const std::filesystem::path& tmp) {
        TiffFile file(tmp, tiff_mode(row_bytes * std::size_t(height) * std::size_t(bands)));
        TIFF* tif = file.get();
        TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, std::uint32_t(width));
        TIFFSetField(tif, TIFFTAG_IMAGELENGTH, std::uint32_t(height));
        TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, 32);
        TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_IEEEFP);
        TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, bands);
        TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_SEPARATE);  // band-sequential, as given
        TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
        if (bands > 1) {
            std::vector<std::uint16_t> extra(std::size_t(bands - 1), EXTRASAMPLE_UNSPECIFIED);
            TIFFSetField(tif, TIFFTAG_EXTRASAMPLES, std::uint16_t(extra.size()), extra.data());
        }
        TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
        TIFFSetField(tif, TIFFTAG_PREDICTOR, PREDICTOR_FLOATINGPOINT);
        TIFFSetField(tif, TIFFTAG_GDAL_NODATA, "nan");
        const std::string xml = gdal_band_metadata_xml(bands, band_names);
        if (!xml.empty()) TIFFSetField(tif, TIFFTAG_GDAL_METADATA, xml.c_str());
        write_geotiff_georef(tif, georef, path.string());
        write_strips(file, height, bands, row_bytes, reinterpret_cast<const std::uint8_t*>(data));
        file.close();
    });
}

void write_u8_image(const std::filesystem::path& path, int width, int height, int channels, const std::uint8_t* data,
                    const geo::Georef* georef, std::optional<int> nodata) {
    check_size(path, width, height, channels);
    if (channels < 1 || channels > 4)
        throw input_error(path.string(), "an 8-bit image has 1 to 4 channels, not " + std::to_string(channels));
    if (written_as(path, ImageWriter::png)) {
        write_atomically(path, [&](const std::filesystem::path& tmp) {
            write_png(tmp, path, width, height, channels, data);
        });
        return;
    }
    if (!written_as(path, ImageWriter::geotiff))
        throw input_error(path.string(), "unknown image extension '" + path.extension().string() + "' (use .png or .tif)");
    const std::size_t row_bytes = std::size_t(width) * std::size_t(channels);
    write_atomically(path, [&](const std::filesystem::path& tmp) {
        TiffFile file(tmp, tiff_mode(row_bytes * std::size_t(height)));
        TIFF* tif = file.get();
        TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, std::uint32_t(width));
        TIFFSetField(tif, TIFFTAG_IMAGELENGTH, std::uint32_t(height));
        TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, 8);
        TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_UINT);
        TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, channels);
        TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
        TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, channels <= 2 ? PHOTOMETRIC_MINISBLACK : PHOTOMETRIC_RGB);
        if (channels == 2 || channels == 4) {
            std::uint16_t alpha = EXTRASAMPLE_UNASSALPHA;
            TIFFSetField(tif, TIFFTAG_EXTRASAMPLES, 1, &alpha);
        }
        TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
        TIFFSetField(tif, TIFFTAG_PREDICTOR, PREDICTOR_HORIZONTAL);
        if (nodata) TIFFSetField(tif, TIFFTAG_GDAL_NODATA, std::to_string(*nodata).c_str());
        if (georef && georef->valid()) write_geotiff_georef(tif, *georef, path.string());
        write_strips(file, height, 1, row_bytes, data);
        file.close();
    });
}

}  // namespace ts::raster
