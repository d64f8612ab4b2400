// GeoTIFF DEMs through libtiff (pixels: strips or tiles, any compression libtiff knows) and
// libgeotiff (georeferencing, core/raster/geotiff_georef). One sample per pixel; int8..int32,
// uint8..uint32, float32/64 heights become float metres; GDAL_NODATA, NaN and +-Inf become
// voids, and so do sparse blocks (no bytes, as GDAL writes with SPARSE_OK) of a file with a
// nodata value. Before the raster is allocated, its blocks are checked against the file's
// size and the memory available.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>
#include <cstring>
#include <limits>

#include "core/dem/decode_limits.hpp"
#include "core/dem/read_dem.hpp"
#include "core/raster/geotiff_georef.hpp"
#include "core/raster/tiff_file.hpp"
#include "core/util/error.hpp"
#include "core/util/memory.hpp"

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

// A height the DEM can hold: finite and within float's range. NaN, +-Inf and float64 values
// beyond +-3.4e38 are no heights at all (and the last would be undefined as a float).
bool is_height(double v) { return std::abs(v) <= double(std::numeric_limits<float>::max()); }

// Copies `rows` x `cols` samples of a decoded block (row stride `block_cols`) into the DEM at
// (col0, row0), marking nodata and non-heights as voids.
void copy_block(Dem& dem, const std::vector<std::uint8_t>& block, int block_cols, int col0, int row0, int cols, int rows,
                SampleType type, std::optional<double> nodata) {
    const int bytes = sample_bytes(type);
    // Nodata compares in the sample's own precision (a float32 file's 9999 is 9999.0f); a
    // nodata value no float can hold matches no float32 sample.
    const bool single = type == SampleType::f32;
    const float nodata_single =
        nodata && is_height(*nodata) ? float(*nodata) : std::numeric_limits<float>::quiet_NaN();
    for (int r = 0; r < rows; ++r) {
        const std::uint8_t* src = block.data() + std::size_t(r) * std::size_t(block_cols) * std::size_t(bytes);
        for (int c = 0; c < cols; ++c) {
            const double v = sample_value(type, src + std::size_t(c) * std::size_t(bytes));
            const std::size_t i = dem.index(col0 + c, row0 + r);
            bool is_void = !is_height(v);
            if (nodata && !is_void) is_void = single ? float(v) == nodata_single : v == *nodata;
            if (is_void) {
                dem.z[i] = std::numeric_limits<float>::quiet_NaN();
                dem.void_mask[i] = 1;
            } else {
                dem.z[i] = float(v);
            }
        }
    }
}

// A sparse block (no bytes, as GDAL writes with SPARSE_OK=TRUE) holds what GDAL specifies:
// the nodata value, so voids, when the file has one, else zeros (GDAL leaves out an all-zero
// block then). The DEM starts as zeros, so only the first case writes anything.
void fill_sparse_block(Dem& dem, int col0, int row0, int cols, int rows, bool has_nodata) {
    if (!has_nodata) return;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const std::size_t i = dem.index(col0 + c, row0 + r);
            dem.z[i] = std::numeric_limits<float>::quiet_NaN();
            dem.void_mask[i] = 1;
        }
}

// The raster's blocks: tiles, or strips of `block_h` whole rows. Block i is at column
// i % across, row i / across of the block grid, as libtiff numbers tiles and strips.
struct Blocks {
    bool tiled = false;
    std::uint32_t block_w = 0, block_h = 0;
    std::uint32_t across = 0, down = 0;
    std::uint64_t count() const { return std::uint64_t(across) * down; }
    const char* noun() const { return tiled ? "tile" : "strip"; }
};

// The bytes libtiff decodes block i into: a whole tile (edge tiles are padded), or the rows
// of the strip that lie inside the image.
std::uint64_t decoded_bytes(const Blocks& b, std::uint64_t i, std::uint32_t height, int sample_size) {
    if (b.tiled) return std::uint64_t(b.block_w) * b.block_h * std::uint64_t(sample_size);
    const std::uint64_t row0 = (i / b.across) * b.block_h;
    const std::uint64_t rows = std::min<std::uint64_t>(b.block_h, height - row0);
    return rows * b.block_w * std::uint64_t(sample_size);
}

// How far a codec can expand its input at most, to check a header's claim against the bytes
// the file holds. These bound the *whole* decoded block (edge padding included): libtiff
// fails a block whose data ends early, so a valid file always stays within them. Deflate
// spends at least two bits on a 258-byte match (1032:1); LZW's 9..12-bit codes for runs that
// grow by one byte per code stay below 1400:1; PackBits repeats a byte at most 128 times for
// 2 bytes (64:1); a ZSTD block of at most 128 KiB takes at least 4 bytes (32768:1). LZMA's
// range coder and LERC (a constant tile is a few dozen bytes at any size) have no useful
// bound, so the rest get a generous one that still refuses a few hundred bytes claiming
// gigabytes.
std::uint64_t max_expansion(std::uint16_t compression) {
    switch (compression) {
        case COMPRESSION_NONE: return 1;
        case COMPRESSION_PACKBITS: return 128;
        case COMPRESSION_LZW: return 2048;
        case COMPRESSION_DEFLATE: case COMPRESSION_ADOBE_DEFLATE: return 1100;
        case COMPRESSION_ZSTD: return 40000;
        default: return 1000000;
    }
}

std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b) {
    return b > std::numeric_limits<std::uint64_t>::max() - a ? std::numeric_limits<std::uint64_t>::max() : a + b;
}

// Refuses a file whose blocks cannot hold what its header claims, before anything the size
// of the raster is allocated: every block must lie inside the file, an uncompressed block
// must hold all its bytes, and the decoded bytes may exceed the compressed bytes (never more
// than the file) by no more than the codec's maximum expansion. Blocks with no bytes are
// sparse (GDAL's SPARSE_OK): they hold nothing, read as nodata and need no bytes.
void check_blocks_fit_file(TIFF* tif, const Blocks& b, std::uint32_t height, int sample_size, std::uint16_t compression,
                           std::uint64_t file_size, const std::string& source) {
    std::uint64_t stored = 0, decoded = 0;
    for (std::uint64_t i = 0; i < b.count(); ++i) {
        int err = 0;
        const std::uint64_t offset = TIFFGetStrileOffsetWithErr(tif, std::uint32_t(i), &err);
        const std::uint64_t bytes = err ? 0 : TIFFGetStrileByteCountWithErr(tif, std::uint32_t(i), &err);
        if (err) throw input_error(source, std::string("corrupt TIFF: cannot read the offset of ") + b.noun() + " " + std::to_string(i));
        if (bytes == 0) continue;
        if (offset > file_size || bytes > file_size - offset)
            throw input_error(source, "truncated TIFF: " + std::string(b.noun()) + " " + std::to_string(i) + " claims bytes " +
                                          std::to_string(offset) + ".." + std::to_string(offset + bytes) + " of a " +
                                          std::to_string(file_size) + "-byte file");
        const std::uint64_t need = decoded_bytes(b, i, height, sample_size);
        if (compression == COMPRESSION_NONE && bytes < need)
            throw input_error(source, "truncated TIFF: uncompressed " + std::string(b.noun()) + " " + std::to_string(i) +
                                          " holds " + std::to_string(bytes) + " bytes, its cells need " + std::to_string(need));
        stored = saturating_add(stored, bytes);
        decoded = saturating_add(decoded, need);
    }
    const std::uint64_t evidence = std::min(stored, file_size);  // blocks sharing bytes prove no more than the file
    const std::uint64_t ratio = max_expansion(compression);
    if (decoded / ratio > evidence)
        throw input_error(source, "truncated or corrupt TIFF: " + format_bytes(decoded) + " of samples cannot come from " +
                                      format_bytes(evidence) + (compression == COMPRESSION_NONE ? " of stored" : " of compressed") +
                                      " data (more than " + std::to_string(ratio) + ":1)");
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

    auto fail = [&](const std::string& what) {
        throw input_error(source, what + (file.last_error().empty() ? "" : " (" + file.last_error() + ")"));
    };
    std::uint16_t compression = COMPRESSION_NONE;
    TIFFGetFieldDefaulted(tif, TIFFTAG_COMPRESSION, &compression);
    if (!TIFFIsCODECConfigured(compression))
        throw input_error(source, "TIFF compression " + std::to_string(compression) + " is not supported by this libtiff");

    const int sample_size = sample_bytes(type);
    Blocks blocks;
    blocks.tiled = TIFFIsTiled(tif);
    if (blocks.tiled) {
        TIFFGetField(tif, TIFFTAG_TILEWIDTH, &blocks.block_w);
        TIFFGetField(tif, TIFFTAG_TILELENGTH, &blocks.block_h);
        if (blocks.block_w == 0 || blocks.block_h == 0) fail("bad tile size");
        // The same cap as the raster's: a bigger tile is a corrupt header, not a DEM.
        if (std::uint64_t(blocks.block_w) * blocks.block_h > (std::uint64_t(1) << 31))
            fail("implausible tile size " + std::to_string(blocks.block_w) + "x" + std::to_string(blocks.block_h));
    } else {
        std::uint32_t rps = height;
        TIFFGetFieldDefaulted(tif, TIFFTAG_ROWSPERSTRIP, &rps);
        blocks.block_w = width;
        blocks.block_h = std::min(std::max<std::uint32_t>(rps, 1), height);
    }
    blocks.across = std::uint32_t((std::uint64_t(width) + blocks.block_w - 1) / blocks.block_w);
    blocks.down = std::uint32_t((std::uint64_t(height) + blocks.block_h - 1) / blocks.block_h);
    // libtiff pads a too-short offset or byte count list with zeros, which would read as
    // sparse blocks: a few hundred bytes would pass for a huge, empty raster.
    for (const char* tag : {"StripOffsets", "StripByteCounts", "TileOffsets", "TileByteCounts"})
        for (const std::string& w : file.warnings())
            if (w.find("Incorrect count for \"" + std::string(tag) + "\"; tag ignored") != std::string::npos)
                throw input_error(source, "corrupt TIFF: its " + std::string(tag) + " list fewer " + blocks.noun() +
                                              "s than the image has (" + w + ")");
    const std::uint64_t listed = blocks.tiled ? TIFFNumberOfTiles(tif) : TIFFNumberOfStrips(tif);
    if (listed != blocks.count())
        fail("corrupt TIFF: " + std::to_string(listed) + " " + blocks.noun() + "s listed for an image of " +
             std::to_string(blocks.count()));
    // One decoded block: a whole tile, or the first (tallest) strip; at most 2^31 cells of 8
    // bytes, so no overflow.
    const std::uint64_t block_bytes = std::uint64_t(blocks.block_w) * blocks.block_h * std::uint64_t(sample_size);
    const std::uint64_t libtiff_block_bytes = blocks.tiled ? TIFFTileSize64(tif) : TIFFStripSize64(tif);
    if (libtiff_block_bytes < block_bytes) fail(std::string("bad ") + blocks.noun() + " size");

    raster::GeoTiffGeoref geo = raster::read_geotiff_georef(tif, int(width), int(height), source);

    std::error_code ec;
    const std::uint64_t file_size = std::filesystem::file_size(path, ec);
    if (ec) throw input_error(source, "cannot read (" + ec.message() + ")");
    check_blocks_fit_file(tif, blocks, height, sample_size, compression, file_size, source);
    require_memory_for(source, "decoding", width, height, block_bytes);

    Dem dem;
    dem.width = int(width);
    dem.height = int(height);
    dem.z.resize(std::size_t(width) * height);
    dem.void_mask.assign(dem.z.size(), 0);
    const std::optional<double> nodata = gdal_nodata(tif);

    std::vector<std::uint8_t> block(block_bytes);
    for (std::uint32_t by = 0; by < blocks.down; ++by)
        for (std::uint32_t bx = 0; bx < blocks.across; ++bx) {
            const std::uint32_t i = by * blocks.across + bx;
            const std::uint32_t x = bx * blocks.block_w, y = by * blocks.block_h;
            const int cols = int(std::min(blocks.block_w, width - x)), rows = int(std::min(blocks.block_h, height - y));
            if (TIFFGetStrileByteCount(tif, i) == 0) {
                fill_sparse_block(dem, int(x), int(y), cols, rows, nodata.has_value());
                continue;
            }
            const auto want = tmsize_t(decoded_bytes(blocks, i, height, sample_size));
            const tmsize_t got = blocks.tiled ? TIFFReadEncodedTile(tif, i, block.data(), want)
                                              : TIFFReadEncodedStrip(tif, i, block.data(), want);
            if (got != want) fail(std::string("truncated or corrupt TIFF ") + blocks.noun() + " " + std::to_string(i));
            copy_block(dem, block, int(blocks.block_w), int(x), int(y), cols, rows, type, nodata);
        }

    dem.georef = std::move(geo.georef);
    dem.vertical_datum = geo.vertical_datum;
    if (dem.vertical_datum == "unknown")
        if (std::string v = vertical_datum_from_gdal_metadata(tif); !v.empty()) dem.vertical_datum = v;
    dem.source = source;
    return dem;
}

}  // namespace ts::dem
