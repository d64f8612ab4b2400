#include "core/raster/float_tiff_reader.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "core/raster/geotiff_georef.hpp"
#include "core/raster/tiff_file.hpp"
#include "core/util/error.hpp"

namespace ts::raster {

FloatTiff read_float_tiff(const std::filesystem::path& path, std::size_t max_values) {
    const TiffFile file(path, "r");
    TIFF* tif = file.get();
    std::uint32_t w = 0, h = 0;
    std::uint16_t spp = 1, bits = 0, format = SAMPLEFORMAT_UINT, planar = PLANARCONFIG_CONTIG;
    TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &w);
    TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &h);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &spp);
    TIFFGetFieldDefaulted(tif, TIFFTAG_BITSPERSAMPLE, &bits);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLEFORMAT, &format);
    TIFFGetFieldDefaulted(tif, TIFFTAG_PLANARCONFIG, &planar);
    const std::string where = path.string();
    if (bits != 32 || format != SAMPLEFORMAT_IEEEFP) throw input_error(where, "is not a float32 raster");
    if (w == 0 || h == 0 || w > 1u << 30 || h > 1u << 30) throw input_error(where, "has no pixels");
    if (std::uint64_t(w) * h * spp > max_values)
        throw input_error(where, "holds " + std::to_string(std::uint64_t(w) * h * spp) + " values, more than " +
                                     std::to_string(max_values) + " fit in memory here");
    FloatTiff out;
    out.width = int(w), out.height = int(h), out.bands = spp;
    out.georef = read_geotiff_georef(tif, out.width, out.height, where).georef;
    char* description = nullptr;
    if (TIFFGetField(tif, TIFFTAG_IMAGEDESCRIPTION, &description) && description) out.image_description = description;
    const std::size_t plane = std::size_t(w) * h;
    out.values.resize(plane * spp);
    auto store = [&](const float* block, std::uint32_t c0, std::uint32_t r0, std::uint32_t bw, std::uint32_t bh,
                     int sample) {
        // One sample of a separate plane, or every sample interleaved.
        const std::uint32_t cols = std::min(bw, w - c0), rows = std::min(bh, h - r0);
        const int first = sample < 0 ? 0 : sample, count = sample < 0 ? spp : 1;
        for (std::uint32_t r = 0; r < rows; ++r)
            for (std::uint32_t c = 0; c < cols; ++c)
                for (int b = 0; b < count; ++b)
                    out.values[std::size_t(first + b) * plane + std::size_t(r0 + r) * w + (c0 + c)] =
                        block[(std::size_t(r) * bw + c) * std::size_t(count) + std::size_t(b)];
    };
    const int planes = planar == PLANARCONFIG_SEPARATE ? spp : 1;
    std::vector<float> block;
    if (TIFFIsTiled(tif)) {
        std::uint32_t tw = 0, th = 0;
        TIFFGetField(tif, TIFFTAG_TILEWIDTH, &tw);
        TIFFGetField(tif, TIFFTAG_TILELENGTH, &th);
        block.resize(std::size_t(TIFFTileSize(tif)) / sizeof(float));
        for (int p = 0; p < planes; ++p)
            for (std::uint32_t r0 = 0; r0 < h; r0 += th)
                for (std::uint32_t c0 = 0; c0 < w; c0 += tw) {
                    const ttile_t t = TIFFComputeTile(tif, c0, r0, 0, tsample_t(p));
                    if (TIFFReadEncodedTile(tif, t, block.data(), tmsize_t(block.size() * sizeof(float))) < 0)
                        throw input_error(where, "cannot decode tile " + std::to_string(t) + " (" +
                                                     (file.last_error().empty() ? "truncated or corrupt" : file.last_error()) + ")");
                    store(block.data(), c0, r0, tw, th, planes > 1 ? p : -1);
                }
    } else {
        std::uint32_t rps = h;
        TIFFGetFieldDefaulted(tif, TIFFTAG_ROWSPERSTRIP, &rps);
        rps = std::min(rps, h);
        block.resize(std::size_t(TIFFStripSize(tif)) / sizeof(float));
        for (int p = 0; p < planes; ++p)
            for (std::uint32_t r0 = 0; r0 < h; r0 += rps) {
                const tstrip_t s = TIFFComputeStrip(tif, r0, tsample_t(p));
                std::fill(block.begin(), block.end(), 0.0f);
                if (TIFFReadEncodedStrip(tif, s, block.data(), tmsize_t(block.size() * sizeof(float))) < 0)
                    throw input_error(where, "cannot decode strip " + std::to_string(s) + " (" +
                                             (file.last_error().empty() ? "truncated or corrupt" : file.last_error()) + ")");
                store(block.data(), 0, r0, w, rps, planes > 1 ? p : -1);
            }
    }
    return out;
}

}  // namespace ts::raster
