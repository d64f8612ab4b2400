// GeoTIFF DEMs through libtiff (pixels: strips or tiles, any compression libtiff knows) and
// libgeotiff (georeferencing, core/raster/geotiff_georef). One sample per pixel; int8..int32,
// uint8..uint32, float32/64 heights become float metres; GDAL_NODATA and NaN become voids.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>
#include <cstring>
#include <limits>

#include "core/dem/read_dem.hpp"
#include "core/raster/geotiff_georef.hpp"
#include "core/raster/tiff_file.hpp"
#include "core/util/error.hpp"

namespace ts::dem {

namespace {

enum class SampleType { u8, i8, u16, i16, u32, i32, f32, f64 };

SampleType sample_type(std::uint16_t format, std::uint16_t bits, const std::string& path) {
    if (format == SAMPLEFORMAT_IEEEFP && bits == 32) return SampleType::f32;
    if (format == SAMPLEFORMAT_IEEEFP && bits == 64) return SampleType::f64;
    const bool is_signed = format == SAMPLEFORMAT_INT;
    if (format == SAMPLEFORMAT_UINT || format == SAMPLEFORMAT_INT || format == SAMPLEFORMAT_VOID) {
        switch (bits) {
            case 8: return is_signed ? SampleType::i8 : SampleType::u8;
            case 16: return is_signed ? SampleType::i16 : SampleType::u16;
            case 32: return is_signed ? SampleType::i32 : SampleType::u32;
            default: break;
        }
    }
    throw input_error(path, "unsupported TIFF sample type (" + std::to_string(bits) + "-bit, format " +
                                std::to_string(format) + "); a DEM needs 8/16/32-bit integers or 32/64-bit floats");
}

int sample_bytes(SampleType t) {
    switch (t) {
        case SampleType::u8: case SampleType::i8: return 1;
        case SampleType::u16: case SampleType::i16: return 2;
        case SampleType::u32: case SampleType::i32: case SampleType::f32: return 4;
        case SampleType::f64: return 8;
    }
    return 1;
}

template <typename T>
double load(const std::uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return double(v);
}

double sample_value(SampleType t, const std::uint8_t* p) {
    switch (t) {
        case SampleType::u8: return load<std::uint8_t>(p);
        case SampleType::i8: return load<std::int8_t>(p);
        case SampleType::u16: return load<std::uint16_t>(p);
        case SampleType::i16: return load<std::int16_t>(p);
        case SampleType::u32: return load<std::uint32_t>(p);
        case SampleType::i32: return load<std::int32_t>(p);
        case SampleType::f32: return load<float>(p);
        case SampleType::f64: return load<double>(p);
    }
    return 0;
}

// Copies `rows` x `cols` samples of a decoded block (row stride `block_cols`) into the DEM at
// (col0, row0), marking nodata and NaN as voids.
void copy_block(Dem& dem, const std::vector<std::uint8_t>& block, int block_cols, int col0, int row0, int cols, int rows,
                SampleType type, std::optional<double> nodata) {
    const int bytes = sample_bytes(type);
    // Nodata compares in the sample's own precision (a float32 file's 9999 is 9999.0f).
    const bool single = type == SampleType::f32;
    for (int r = 0; r < rows; ++r) {
        const std::uint8_t* src = block.data() + std::size_t(r) * std::size_t(block_cols) * std::size_t(bytes);
        for (int c = 0; c < cols; ++c) {
            const double v = sample_value(type, src + std::size_t(c) * std::size_t(bytes));
            const std::size_t i = dem.index(col0 + c, row0 + r);
            bool is_void = std::isnan(v);
            if (nodata && !is_void) is_void = single ? float(v) == float(*nodata) : v == *nodata;
            if (is_void) {
                dem.z[i] = std::numeric_limits<float>::quiet_NaN();
                dem.void_mask[i] = 1;
            } else {
                dem.z[i] = float(v);
            }
        }
    }
}

std::optional<double> gdal_nodata(TIFF* tif) {
    const char* text = nullptr;
    if (!TIFFGetField(tif, TIFFTAG_GDAL_NODATA, &text) || !text) return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (end == text) return std::nullopt;
    return v;
}

// Copernicus DEM GeoTIFFs name their vertical datum only in GDAL metadata copied from DTED
// headers (DTED_VerticalDatum = E96 / E08), not in a VerticalCSTypeGeoKey.
std::string vertical_datum_from_gdal_metadata(TIFF* tif) {
    const char* xml = nullptr;
    if (!TIFFGetField(tif, TIFFTAG_GDAL_METADATA, &xml) || !xml) return {};
    const std::string text = xml;
    const std::string key = "name=\"DTED_VerticalDatum\">";
    const auto at = text.find(key);
    if (at == std::string::npos) return {};
    const std::string code = text.substr(at + key.size(), 3);
    if (code == "E96") return "EGM96 geoid";
    if (code == "E08") return "EGM2008 geoid";
    return {};
}

}  // namespace

Dem read_geotiff(const std::filesystem::path& path) {
    const std::string source = path.string();
    raster::TiffFile file(path, "r");
    TIFF* tif = file.get();

    std::uint32_t width = 0, height = 0;
    std::uint16_t spp = 1, bits = 8, format = SAMPLEFORMAT_UINT;
    TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &width);
    TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &height);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &spp);
    TIFFGetFieldDefaulted(tif, TIFFTAG_BITSPERSAMPLE, &bits);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLEFORMAT, &format);
    if (width == 0 || height == 0) throw input_error(source, "TIFF image of size 0");
    if (std::uint64_t(width) * height > (std::uint64_t(1) << 31))
        throw input_error(source, "raster too large (" + std::to_string(width) + "x" + std::to_string(height) + ")");
    // One sample per pixel, so contiguous and separate planar layouts read the same.
    if (spp != 1)
        throw input_error(source, "has " + std::to_string(spp) +
                                      " samples per pixel (a colour image?); a DEM has one height band");
    const SampleType type = sample_type(format, bits, source);

    raster::GeoTiffGeoref geo = raster::read_geotiff_georef(tif, int(width), int(height), source);

    Dem dem;
    dem.width = int(width);
    dem.height = int(height);
    dem.z.resize(std::size_t(width) * height);
    dem.void_mask.assign(dem.z.size(), 0);
    const std::optional<double> nodata = gdal_nodata(tif);

    auto fail = [&](const char* what) {
        throw input_error(source, std::string(what) + (file.last_error().empty() ? "" : " (" + file.last_error() + ")"));
    };
    if (TIFFIsTiled(tif)) {
        std::uint32_t tw = 0, th = 0;
        TIFFGetField(tif, TIFFTAG_TILEWIDTH, &tw);
        TIFFGetField(tif, TIFFTAG_TILELENGTH, &th);
        if (tw == 0 || th == 0) fail("bad tile size");
        std::vector<std::uint8_t> block(std::size_t(TIFFTileSize(tif)));
        if (block.size() < std::size_t(tw) * th * std::size_t(sample_bytes(type))) fail("bad tile size");
        for (std::uint32_t y = 0; y < height; y += th)
            for (std::uint32_t x = 0; x < width; x += tw) {
                if (TIFFReadEncodedTile(tif, TIFFComputeTile(tif, x, y, 0, 0), block.data(), tmsize_t(block.size())) < 0)
                    fail("truncated or corrupt TIFF tile");
                copy_block(dem, block, int(tw), int(x), int(y), int(std::min(tw, width - x)), int(std::min(th, height - y)),
                           type, nodata);
            }
    } else {
        std::uint32_t rps = height;
        TIFFGetFieldDefaulted(tif, TIFFTAG_ROWSPERSTRIP, &rps);
        rps = std::min(std::max<std::uint32_t>(rps, 1), height);
        std::vector<std::uint8_t> block(std::size_t(TIFFStripSize(tif)));
        if (block.size() < std::size_t(width) * rps * std::size_t(sample_bytes(type))) fail("bad strip size");
        for (std::uint32_t y = 0; y < height; y += rps) {
            const std::uint32_t rows = std::min(rps, height - y);
            if (TIFFReadEncodedStrip(tif, TIFFComputeStrip(tif, y, 0), block.data(),
                                     tmsize_t(std::size_t(width) * rows * std::size_t(sample_bytes(type)))) < 0)
                fail("truncated or corrupt TIFF strip");
            copy_block(dem, block, int(width), 0, int(y), int(width), int(rows), type, nodata);
        }
    }

    dem.georef = std::move(geo.georef);
    dem.vertical_datum = geo.vertical_datum;
    if (dem.vertical_datum == "unknown")
        if (std::string v = vertical_datum_from_gdal_metadata(tif); !v.empty()) dem.vertical_datum = v;
    dem.source = source;
    return dem;
}

}  // namespace ts::dem
