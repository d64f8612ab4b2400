#include "core/raster/png_writer.hpp"

#include <libdeflate.h>  // crc32

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "core/raster/zlib_stream.hpp"
#include "core/util/error.hpp"
#include "core/util/uninitialised_vector.hpp"

namespace ts::raster {
namespace {

using Bytes = UninitialisedVector<std::uint8_t>;

// out[i] = row[i] - predictor for one row of n bytes, bpp bytes per pixel; `prior` is the row
// above (zeros for the top row). The loops have no carried dependency (the predictors read the
// unfiltered bytes), so GCC vectorises them (CMakeLists.txt: dynamic cost model for this file).
void filter_row(PngFilter filter, const std::uint8_t* __restrict row, const std::uint8_t* __restrict prior,
                std::uint8_t* __restrict out, std::size_t n, std::size_t bpp) {
    const std::size_t lead = std::min(bpp, n);  // the first pixel: no left neighbour (a = c = 0)
    switch (filter) {
        case PngFilter::none:
            std::copy(row, row + n, out);
            return;
        case PngFilter::sub:
            std::copy(row, row + lead, out);
            for (std::size_t i = lead; i < n; ++i) out[i] = std::uint8_t(row[i] - row[i - bpp]);
            return;
        case PngFilter::up:
            for (std::size_t i = 0; i < n; ++i) out[i] = std::uint8_t(row[i] - prior[i]);
            return;
        case PngFilter::average:
            for (std::size_t i = 0; i < lead; ++i) out[i] = std::uint8_t(row[i] - (prior[i] >> 1));
            for (std::size_t i = lead; i < n; ++i)
                out[i] = std::uint8_t(row[i] - ((unsigned(row[i - bpp]) + prior[i]) >> 1));
            return;
        case PngFilter::paeth:
            // With a = c = 0 the Paeth predictor is b (the byte above).
            for (std::size_t i = 0; i < lead; ++i) out[i] = std::uint8_t(row[i] - prior[i]);
            for (std::size_t i = lead; i < n; ++i) {
                const int a = row[i - bpp], b = prior[i], c = prior[i - bpp];
                const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
                const int predictor = (pa <= pb && pa <= pc) ? a : (pb <= pc ? b : c);
                out[i] = std::uint8_t(row[i] - predictor);
            }
            return;
        case PngFilter::trial: break;
    }
}

struct Picture {
    int width, height;
    std::size_t bpp, row_bytes;
    const std::uint8_t* data;
    const std::uint8_t* row(int y) const { return data + std::size_t(y) * row_bytes; }
};

// Appends rows [y0, y1) filtered with `filter`, each after its filter-type byte.
void filter_rows(const Picture& p, PngFilter filter, int y0, int y1, const std::uint8_t* zero_row, std::uint8_t* out) {
    for (int y = y0; y < y1; ++y, out += p.row_bytes + 1) {
        out[0] = std::uint8_t(filter);
        filter_row(filter, p.row(y), y > 0 ? p.row(y - 1) : zero_row, out + 1, p.row_bytes, p.bpp);
    }
}

// The filter with the smallest compressed sample: 8-row bands, one in the middle of every 256
// rows (at least one band), each band filtered against the real row above it. Up and average
// are not tried: on rendered maps, perspective views and quick-looks they never compressed
// best, and on map frames at a low sun average won the sample but not the picture (the sample
// misses none's long-distance matches), costing 3-5%.
PngFilter choose_filter(const Picture& p, const PngEncoding& encoding, const std::uint8_t* zero_row) {
    constexpr int kBandRows = 8, kBandSpacing = 256;
    std::vector<std::pair<int, int>> bands;
    for (int start = 0; start < p.height; start += kBandSpacing) {
        const int stretch = std::min(kBandSpacing, p.height - start);
        const int y0 = start + std::max(0, (stretch - kBandRows) / 2);
        bands.emplace_back(y0, std::min(p.height, y0 + kBandRows));
    }
    std::size_t rows = 0;
    for (const auto& [y0, y1] : bands) rows += std::size_t(y1 - y0);
    Bytes sample(rows * (p.row_bytes + 1));
    Bytes compressed(zlib_bound(sample.size()));
    PngFilter best = PngFilter::none;
    std::size_t best_size = SIZE_MAX;
    // Ties keep the earlier, cheaper-to-compute filter.
    for (PngFilter f : {PngFilter::none, PngFilter::sub, PngFilter::paeth}) {
        std::uint8_t* out = sample.data();
        for (const auto& [y0, y1] : bands) {
            filter_rows(p, f, y0, y1, zero_row, out);
            out += std::size_t(y1 - y0) * (p.row_bytes + 1);
        }
        const std::size_t size = zlib_compress(encoding.deflater, encoding.level, sample.data(), sample.size(),
                                               compressed.data(), compressed.size());
        if (size != 0 && size < best_size) best = f, best_size = size;
    }
    return best;
}

void put_u32(std::uint8_t* p, std::uint32_t v) {
    p[0] = std::uint8_t(v >> 24), p[1] = std::uint8_t(v >> 16), p[2] = std::uint8_t(v >> 8), p[3] = std::uint8_t(v);
}

// Appends one chunk: length, type, data, CRC-32 of type + data (PNG specification, section 5.3).
void append_chunk(std::vector<std::uint8_t>& out, const char (&type)[5], const std::uint8_t* data, std::size_t n) {
    std::uint8_t head[8];
    put_u32(head, std::uint32_t(n));
    std::copy(type, type + 4, head + 4);
    std::uint8_t crc[4];
    std::uint32_t sum = libdeflate_crc32(0, head + 4, 4);
    if (n) sum = libdeflate_crc32(sum, data, n);  // (a null buffer would restart the sum)
    put_u32(crc, sum);
    out.insert(out.end(), head, head + 8);
    if (n) out.insert(out.end(), data, data + n);
    out.insert(out.end(), crc, crc + 4);
}

}  // namespace

std::vector<std::uint8_t> encode_png(int width, int height, int channels, const std::uint8_t* data,
                                     const PngEncoding& encoding, const std::string& shown_path) {
    std::uint8_t colour_type = 0;
    switch (channels) {
        case 1: colour_type = 0; break;  // greyscale
        case 2: colour_type = 4; break;  // greyscale with alpha
        case 3: colour_type = 2; break;  // truecolour
        case 4: colour_type = 6; break;  // truecolour with alpha
        default: throw input_error(shown_path, "a PNG has 1 to 4 channels, not " + std::to_string(channels));
    }
    if (encoding.level < 0 || encoding.level > max_level(encoding.deflater))
        throw input_error(shown_path, "PNG compression level must be 0.." +
                                                   std::to_string(max_level(encoding.deflater)) + " with " +
                                                   (encoding.deflater == Deflater::isal ? "ISA-L" : "libdeflate"));
    if (width <= 0 || height <= 0 || width > 0x7fffffff / channels)
        throw input_error(shown_path, "cannot write a " + std::to_string(width) + "x" + std::to_string(height) + " PNG");

    const Picture p{width, height, std::size_t(channels), std::size_t(width) * std::size_t(channels), data};
    const std::vector<std::uint8_t> zero_row(p.row_bytes, 0);
    const PngFilter filter =
        encoding.filter == PngFilter::trial ? choose_filter(p, encoding, zero_row.data()) : encoding.filter;
    Bytes filtered(std::size_t(height) * (p.row_bytes + 1));
    filter_rows(p, filter, 0, height, zero_row.data(), filtered.data());
    Bytes stream(zlib_bound(filtered.size()));
    const std::size_t stream_size = zlib_compress(encoding.deflater, encoding.level, filtered.data(),
                                                  filtered.size(), stream.data(), stream.size());
    if (stream_size == 0) throw input_error(shown_path, "writing PNG failed: compression failed");

    std::uint8_t ihdr[13];
    put_u32(ihdr, std::uint32_t(width));
    put_u32(ihdr + 4, std::uint32_t(height));
    ihdr[8] = 8;  // bits per sample
    ihdr[9] = colour_type;
    ihdr[10] = ihdr[11] = ihdr[12] = 0;  // deflate, adaptive filtering (per-row filter byte), no interlace

    std::vector<std::uint8_t> out;
    out.reserve(stream_size + 64);
    static constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    out.insert(out.end(), kSignature, kSignature + sizeof kSignature);
    append_chunk(out, "IHDR", ihdr, sizeof ihdr);
    // A chunk holds at most 2^31 - 1 bytes; decoders join consecutive IDATs into one stream.
    constexpr std::size_t kMaxIdat = std::size_t(1) << 30;
    for (std::size_t at = 0; at < stream_size; at += kMaxIdat)
        append_chunk(out, "IDAT", stream.data() + at, std::min(kMaxIdat, stream_size - at));
    append_chunk(out, "IEND", nullptr, 0);
    return out;
}

void write_png(const std::filesystem::path& file, const std::filesystem::path& shown_path, int width, int height,
               int channels, const std::uint8_t* data, const PngEncoding& encoding) {
    const std::vector<std::uint8_t> png = encode_png(width, height, channels, data, encoding, shown_path.string());
    std::FILE* f = std::fopen(file.c_str(), "wb");
    if (!f) throw input_error(shown_path.string(), "writing PNG failed: cannot open the file");
    const bool written = std::fwrite(png.data(), 1, png.size(), f) == png.size();
    const bool closed = std::fclose(f) == 0;
    if (!written || !closed)
        throw input_error(shown_path.string(), "writing PNG failed: cannot write the file (disk full?)");
}

}  // namespace ts::raster
