#include "core/dem/geotiff_header.hpp"

#include <algorithm>
#include <climits>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>

#include "core/geo/crs.hpp"
#include "core/raster/geotiff_georef.hpp"
#include "core/util/error.hpp"
#include "core/util/memory.hpp"

namespace ts::dem {

namespace {

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
void check_blocks_fit_file(TIFF* tif, const GeoTiffHeader& h, std::uint64_t file_size, const std::string& source) {
    const TiffBlocks& b = h.blocks;
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
        const std::uint64_t need = h.decoded_bytes(i);
        if (h.compression == COMPRESSION_NONE && bytes < need)
            throw input_error(source, "truncated TIFF: uncompressed " + std::string(b.noun()) + " " + std::to_string(i) +
                                          " holds " + std::to_string(bytes) + " bytes, its cells need " + std::to_string(need));
        stored = saturating_add(stored, bytes);
        decoded = saturating_add(decoded, need);
    }
    const std::uint64_t evidence = std::min(stored, file_size);  // blocks sharing bytes prove no more than the file
    const std::uint64_t ratio = max_expansion(h.compression);
    if (decoded / ratio > evidence)
        throw input_error(source, "truncated or corrupt TIFF: " + format_bytes(decoded) + " of samples cannot come from " +
                                      format_bytes(evidence) + (h.compression == COMPRESSION_NONE ? " of stored" : " of compressed") +
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

// The unit of the heights: GDAL's band unit type (GDAL_METADATA, role "unittype"), else
// VerticalUnitsGeoKey, else the unit of the vertical CRS's axis (EPSG:6360 is in US survey
// feet); metres when the file is silent. A unit that is not a length is refused: heights taken
// as metres in the wrong unit would exaggerate the relief 3.28 times without a word.
geo::LinearUnit height_unit(TIFF* tif, const raster::GeoTiffGeoref& geo, const std::string& source) {
    const char* xml = nullptr;
    if (TIFFGetField(tif, TIFFTAG_GDAL_METADATA, &xml) && xml) {
        const std::string text = xml;
        const auto role = text.find("role=\"unittype\"");
        if (role != std::string::npos) {
            const auto from = text.find('>', role), to = text.find('<', role);
            std::string name = from != std::string::npos && to != std::string::npos && to > from ? text.substr(from + 1, to - from - 1) : "";
            std::string key;
            for (char c : name)
                if (!std::isspace(static_cast<unsigned char>(c))) key += char(std::tolower(static_cast<unsigned char>(c)));
            if (key.empty() || key == "m" || key == "metre" || key == "meter" || key == "metres" || key == "meters" ||
                key == "unknown")
                return {"metre", 1.0};
            if (key == "ft" || key == "foot" || key == "feet" || key == "internationalfoot" || key == "ftintl" ||
                key == "ft_intl")
                return {"foot", 0.3048};
            if (key == "ussurveyfoot" || key == "ussurveyfeet" || key == "ftus" || key == "us-ft" || key == "usft" ||
                key == "foot_us" || key == "usfoot")
                return {"US survey foot", 1200.0 / 3937.0};
            throw input_error(source, "heights in '" + name + "' (its GDAL unit type): terrashade reads metres and feet");
        }
    }
    if (geo.vertical_units_code) {
        if (const auto u = geo::linear_unit(geo.vertical_units_code)) return *u;
        throw input_error(source, "heights in EPSG unit " + std::to_string(geo.vertical_units_code) +
                                      " (VerticalUnitsGeoKey), not a length terrashade knows");
    }
    if (geo.vertical_cs_code)
        if (const auto u = geo::vertical_crs_unit(geo.vertical_cs_code)) return *u;
    return {"metre", 1.0};
}

// Who made the heights: the copyright tag, else what a Copernicus DEM's DTED metadata says (its
// heights come from the TanDEM-X mission); empty when the file is silent.
std::string credit_from_tiff(TIFF* tif) {
    const char* copyright = nullptr;
    if (TIFFGetField(tif, TIFFTAG_COPYRIGHT, &copyright) && copyright) {
        std::string c = copyright;
        while (!c.empty() && std::isspace(static_cast<unsigned char>(c.back()))) c.pop_back();
        if (!c.empty()) return c;
    }
    const char* xml = nullptr;
    if (TIFFGetField(tif, TIFFTAG_GDAL_METADATA, &xml) && xml &&
        std::string(xml).find("name=\"DTED_DigitizingSystem\">TANDEMX") != std::string::npos)
        return "Copernicus DEM (TanDEM-X) \u00a9 DLR e.V., Airbus Defence and Space, provided under COPERNICUS by the EU and ESA";
    return {};
}

}  // namespace

GeoTiffHeader::Cells GeoTiffHeader::cells(std::uint32_t i) const {
    const std::uint32_t x = (i % blocks.across) * blocks.block_w, y = (i / blocks.across) * blocks.block_h;
    Cells c;
    c.col0 = int(x);
    c.row0 = int(y);
    c.cols = int(std::min<std::uint64_t>(blocks.block_w, std::uint64_t(layout.width) - x));
    c.rows = int(std::min<std::uint64_t>(blocks.block_h, std::uint64_t(layout.height) - y));
    return c;
}

std::uint64_t GeoTiffHeader::decoded_bytes(std::uint64_t i) const {
    const auto sample_size = std::uint64_t(sample_bytes(type));
    if (blocks.tiled) return std::uint64_t(blocks.block_w) * blocks.block_h * sample_size;
    const std::uint64_t row0 = (i / blocks.across) * blocks.block_h;
    const std::uint64_t rows = std::min<std::uint64_t>(blocks.block_h, std::uint64_t(layout.height) - row0);
    return rows * blocks.block_w * sample_size;
}

GeoTiffHeader read_geotiff_header(const raster::TiffFile& file, std::uint64_t max_cells) {
    const std::string& source = file.path();
    TIFF* tif = file.get();

    std::uint32_t width = 0, height = 0;
    std::uint16_t spp = 1, bits = 8, format = SAMPLEFORMAT_UINT;
    TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &width);
    TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &height);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &spp);
    TIFFGetFieldDefaulted(tif, TIFFTAG_BITSPERSAMPLE, &bits);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLEFORMAT, &format);
    if (width == 0 || height == 0) throw input_error(source, "TIFF image of size 0");
    if (std::uint64_t(width) * height > max_cells || width > std::uint32_t(INT_MAX) || height > std::uint32_t(INT_MAX))
        throw input_error(source, "raster too large (" + std::to_string(width) + "x" + std::to_string(height) + ")");
    // One sample per pixel, so contiguous and separate planar layouts read the same.
    if (spp != 1)
        throw input_error(source, "has " + std::to_string(spp) +
                                      " samples per pixel (a colour image?); a DEM has one height band");
    GeoTiffHeader h;
    h.type = sample_type(format, bits, source);
    h.layout.width = int(width);
    h.layout.height = int(height);
    h.layout.source = source;

    auto fail = [&](const std::string& what) {
        throw input_error(source, what + (file.last_error().empty() ? "" : " (" + file.last_error() + ")"));
    };
    TIFFGetFieldDefaulted(tif, TIFFTAG_COMPRESSION, &h.compression);
    if (!TIFFIsCODECConfigured(h.compression))
        throw input_error(source, "TIFF compression " + std::to_string(h.compression) + " is not supported by this libtiff");

    TiffBlocks& blocks = h.blocks;
    blocks.tiled = TIFFIsTiled(tif);
    if (blocks.tiled) {
        TIFFGetField(tif, TIFFTAG_TILEWIDTH, &blocks.block_w);
        TIFFGetField(tif, TIFFTAG_TILELENGTH, &blocks.block_h);
        if (blocks.block_w == 0 || blocks.block_h == 0) fail("bad tile size");
        // The same cap as a whole raster's: a bigger tile is a corrupt header, not a DEM.
        if (std::uint64_t(blocks.block_w) * blocks.block_h > (std::uint64_t(1) << 31))
            fail("implausible tile size " + std::to_string(blocks.block_w) + "x" + std::to_string(blocks.block_h));
    } else {
        std::uint32_t rps = height;
        TIFFGetFieldDefaulted(tif, TIFFTAG_ROWSPERSTRIP, &rps);
        blocks.block_w = width;
        blocks.block_h = std::min(std::max<std::uint32_t>(rps, 1), height);
        // Only reachable without a cap on the raster: a strip is decoded whole, so one past
        // the tile cap cannot be read by windows in bounded memory.
        if (std::uint64_t(blocks.block_w) * blocks.block_h > (std::uint64_t(1) << 31))
            fail("strips of " + std::to_string(blocks.block_w) + "x" + std::to_string(blocks.block_h) +
                 " cells are too large to decode; rewrite it tiled or with fewer rows per strip");
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
    // One decoded block: at most 2^31 cells of 8 bytes, so no overflow.
    h.block_bytes = std::uint64_t(blocks.block_w) * blocks.block_h * std::uint64_t(sample_bytes(h.type));
    const std::uint64_t libtiff_block_bytes = blocks.tiled ? TIFFTileSize64(tif) : TIFFStripSize64(tif);
    if (libtiff_block_bytes < h.block_bytes) fail(std::string("bad ") + blocks.noun() + " size");

    raster::GeoTiffGeoref geo = raster::read_geotiff_georef(tif, int(width), int(height), source);

    std::error_code ec;
    const std::uint64_t file_size = std::filesystem::file_size(source, ec);
    if (ec) throw input_error(source, "cannot read (" + ec.message() + ")");
    check_blocks_fit_file(tif, h, file_size, source);

    h.nodata = gdal_nodata(tif);
    const geo::LinearUnit unit = height_unit(tif, geo, source);
    h.metres_per_unit = unit.metres;
    h.layout.height_unit = unit.metres == 1.0 ? "metre" : unit.name;
    h.layout.georef = std::move(geo.georef);
    h.layout.vertical_datum = geo.vertical_datum;
    if (h.layout.vertical_datum == "unknown")
        if (std::string v = vertical_datum_from_gdal_metadata(tif); !v.empty()) h.layout.vertical_datum = v;
    h.layout.credit = credit_from_tiff(tif);
    return h;
}

bool read_geotiff_block(const raster::TiffFile& file, const GeoTiffHeader& header, std::uint32_t i, std::uint8_t* out) {
    TIFF* tif = file.get();
    if (TIFFGetStrileByteCount(tif, i) == 0) return false;
    const auto want = tmsize_t(header.decoded_bytes(i));
    const tmsize_t got = header.blocks.tiled ? TIFFReadEncodedTile(tif, i, out, want) : TIFFReadEncodedStrip(tif, i, out, want);
    if (got != want)
        throw input_error(file.path(), std::string("truncated or corrupt TIFF ") + header.blocks.noun() + " " + std::to_string(i) +
                                           (file.last_error().empty() ? "" : " (" + file.last_error() + ")"));
    return true;
}

}  // namespace ts::dem
