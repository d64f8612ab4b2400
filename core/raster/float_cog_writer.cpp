#include "core/raster/float_cog_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "core/raster/cog_writer.hpp"
#include "core/raster/gdal_band_metadata.hpp"
#include "core/raster/geotiff_georef.hpp"
#include "core/raster/image_writer_registry.hpp"
#include "core/raster/tiff_file.hpp"
#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"

namespace ts::raster {
namespace {

constexpr float kNoData = std::numeric_limits<float>::quiet_NaN();

// One resolution level: `bands` planes of width*height, band-sequential.
struct FloatLevel {
    int width = 0, height = 0;
    std::vector<float> owned;
    const float* data = nullptr;

    std::size_t plane_size() const { return std::size_t(width) * std::size_t(height); }
    const float* plane(int band) const { return data + std::size_t(band) * plane_size(); }
};

// Each 2x2 block's mean over its finite values (a last odd row or column from what it has):
// void texels neither pull an edge towards anything nor spread, and a block of voids stays NaN.
FloatLevel halved_finite_mean(const FloatLevel& in, int bands) {
    FloatLevel out;
    out.width = (in.width + 1) / 2, out.height = (in.height + 1) / 2;
    out.owned.resize(out.plane_size() * std::size_t(bands));
    for (int b = 0; b < bands; ++b) {
        const float* src = in.plane(b);
        float* dst = out.owned.data() + std::size_t(b) * out.plane_size();
        for (int r = 0; r < out.height; ++r)
            for (int c = 0; c < out.width; ++c) {
                double sum = 0;
                int n = 0;
                for (int dr = 0; dr < 2; ++dr)
                    for (int dc = 0; dc < 2; ++dc) {
                        const int sr = 2 * r + dr, sc = 2 * c + dc;
                        if (sr >= in.height || sc >= in.width) continue;
                        const float v = src[std::size_t(sr) * std::size_t(in.width) + std::size_t(sc)];
                        if (std::isfinite(v)) sum += double(v), ++n;
                    }
                dst[std::size_t(r) * std::size_t(out.width) + std::size_t(c)] = n ? float(sum / n) : kNoData;
            }
    }
    out.data = out.owned.data();
    return out;
}

// What only the full resolution's IFD carries (GDAL reads them there for every level).
struct MainImageTags {
    const geo::Georef* georef;
    std::string band_metadata_xml;
    std::string image_description;
};

void write_float_directory(TiffFile& file, const FloatLevel& level, int bands, const MainImageTags* main) {
    TIFF* tif = file.get();
    TIFFSetField(tif, TIFFTAG_SUBFILETYPE, main ? 0 : FILETYPE_REDUCEDIMAGE);
    TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, std::uint32_t(level.width));
    TIFFSetField(tif, TIFFTAG_IMAGELENGTH, std::uint32_t(level.height));
    TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, 32);
    TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_IEEEFP);
    TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, bands);
    TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_SEPARATE);
    TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
    if (bands > 1) {
        std::vector<std::uint16_t> extra(std::size_t(bands - 1), EXTRASAMPLE_UNSPECIFIED);
        TIFFSetField(tif, TIFFTAG_EXTRASAMPLES, std::uint16_t(extra.size()), extra.data());
    }
    TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
    TIFFSetField(tif, TIFFTAG_PREDICTOR, PREDICTOR_FLOATINGPOINT);
    TIFFSetField(tif, TIFFTAG_TILEWIDTH, std::uint32_t(kCogTileSize));
    TIFFSetField(tif, TIFFTAG_TILELENGTH, std::uint32_t(kCogTileSize));
    // On every level, as GDAL writes its overviews: a reader of one IFD alone sees the voids.
    TIFFSetField(tif, TIFFTAG_GDAL_NODATA, "nan");
    if (main) {
        if (!main->band_metadata_xml.empty())
            TIFFSetField(tif, TIFFTAG_GDAL_METADATA, main->band_metadata_xml.c_str());
        if (!main->image_description.empty())
            TIFFSetField(tif, TIFFTAG_IMAGEDESCRIPTION, main->image_description.c_str());
        write_geotiff_georef(tif, *main->georef, file.path());
    }
    const std::size_t t = std::size_t(kCogTileSize);
    std::vector<float> tile(t * t);
    for (int b = 0; b < bands; ++b) {
        const float* plane = level.plane(b);
        for (int r0 = 0; r0 < level.height; r0 += kCogTileSize)
            for (int c0 = 0; c0 < level.width; c0 += kCogTileSize) {
                // Edge tiles are padded with nodata, as GDAL pads them.
                std::fill(tile.begin(), tile.end(), kNoData);
                const int rows = std::min(kCogTileSize, level.height - r0);
                const int cols = std::min(kCogTileSize, level.width - c0);
                for (int r = 0; r < rows; ++r)
                    std::memcpy(tile.data() + std::size_t(r) * t,
                                plane + std::size_t(r0 + r) * std::size_t(level.width) + std::size_t(c0),
                                std::size_t(cols) * sizeof(float));
                const ttile_t index = TIFFComputeTile(tif, std::uint32_t(c0), std::uint32_t(r0), 0, tsample_t(b));
                if (TIFFWriteEncodedTile(tif, index, tile.data(), tmsize_t(tile.size() * sizeof(float))) < 0)
                    throw input_error(file.path(), "writing TIFF failed: " + file.last_error());
            }
    }
    if (!TIFFWriteDirectory(tif)) throw input_error(file.path(), "writing TIFF failed: " + file.last_error());
}

// BigTIFF when the tiles, uncompressed, would pass 3 GiB (as raster_writer's float GeoTIFFs;
// GDAL's BIGTIFF=IF_SAFER is alike): the compressed size is known only once written, and a
// classic TIFF found too large then would throw away the whole computation.
bool needs_bigtiff(int width, int height, int bands) {
    const std::uint64_t tile_bytes = std::uint64_t(kCogTileSize) * kCogTileSize * sizeof(float);
    auto tiles = [](int w, int h) {
        const int t = kCogTileSize;
        return std::uint64_t((w + t - 1) / t) * std::uint64_t((h + t - 1) / t);
    };
    std::uint64_t n = tiles(width, height);
    for (const auto& [w, h] : cog_overview_sizes(width, height)) n += tiles(w, h);
    return n * std::uint64_t(bands) * tile_bytes > (std::uint64_t(3) << 30);
}

}  // namespace

void write_float_cog(const std::filesystem::path& path, int width, int height, int bands, const float* data,
                     const geo::Georef& georef, const std::vector<std::string>& descriptions,
                     const std::vector<std::string>& units, const std::string& image_description) {
    if (!written_as(path, ImageWriter::geotiff))
        throw input_error(path.string(), "unknown extension for a float raster (use .tif or .tiff)");
    if (width <= 0 || height <= 0 || bands <= 0)
        throw input_error(path.string(), "cannot write an empty raster (" + std::to_string(width) + "x" +
                                             std::to_string(height) + "x" + std::to_string(bands) + ")");
    // The TIFF's SamplesPerPixel and ExtraSamples count are 16-bit.
    if (bands > 65535) throw input_error(path.string(), std::to_string(bands) + " bands: a TIFF holds at most 65535");
    if (!georef.valid()) throw input_error(path.string(), "a Cloud-Optimized GeoTIFF needs georeferencing");
    const MainImageTags main{&georef, gdal_band_metadata_xml(bands, descriptions, units), image_description};
    write_atomically(path, [&](const std::filesystem::path& tmp) {
        {
            // Little-endian, as lay_out_as_cog reads.
            TiffFile file(tmp, needs_bigtiff(width, height, bands) ? "w8l" : "wl");
            FloatLevel level;
            level.width = width, level.height = height, level.data = data;
            write_float_directory(file, level, bands, &main);
            while (level.width > kCogTileSize || level.height > kCogTileSize) {
                level = halved_finite_mean(level, bands);
                write_float_directory(file, level, bands, nullptr);
            }
            file.close();
        }
        lay_out_as_cog(tmp, path.string());
    });
}

}  // namespace ts::raster
