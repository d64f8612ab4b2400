// `terrashade bench dem N --out FILE.tif`: the synthetic mosaic of `bench tiles synthetic:N`
// (synthetic_mosaic.hpp) as an N x N int16 GeoTIFF, for DEMs larger than memory (the streamed
// flythrough: tests/cli/fly_stream_cli_test.cpp). Written one band of tile rows at a time, so
// its memory stays ~N x tile x 8 bytes whatever N is: the grid itself is never held.
//
// The file is what SRTM mosaics usually are after gdal_translate: tiled (--tile), deflate with
// the horizontal predictor, EPSG:4326, 1 arc-second cells, GDAL_NODATA -32768 (never used: the
// noise has no voids). Heights are the noise rounded to whole metres (int16 holds no more).
// The predictor and deflate of each tile run here, in parallel over a band's tiles, and libtiff
// writes the encoded bytes (TIFFWriteRawTile): its own codec would encode one tile at a time on
// one core. N = 8193 takes 4.5 s on 2 cores, 3.2 s of it the noise (42 MB, 42 MB resident).
#include <tiffio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/bench/bench_command.hpp"
#include "app/bench/study/synthetic_mosaic.hpp"
#include "app/io_plan.hpp"
#include "core/raster/geotiff_georef.hpp"
#include "core/raster/tiff_file.hpp"
#include "core/raster/zlib_stream.hpp"
#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"
#include "core/util/memory.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/progress_bar.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::app {
namespace {

constexpr int kMinSide = 2, kMaxSide = 200000;
constexpr std::int16_t kNodata = -32768;
// libdeflate at zlib's default level: the file's size matters more here than the second.
constexpr raster::Deflater kDeflater = raster::Deflater::libdeflate;
constexpr int kDeflateLevel = 6;

struct BenchDemArgs {
    int n = -1;  // -1: not given
    std::string out;
    int tile = 256;
    int threads = 0;
};

struct Extremes {
    std::int16_t lo = std::numeric_limits<std::int16_t>::max(), hi = std::numeric_limits<std::int16_t>::min();
};

// One tile of the band, rows [0, rows) of `heights` (n columns) from column col0, padded to a
// whole tile with zeros (readers ignore the padding), the predictor applied (each sample
// minus its left neighbour, modulo 2^16 as TIFF's predictor 2), deflated into `packed`.
void encode_tile(const std::vector<std::int16_t>& heights, int n, int rows, int col0, int tile,
                 std::vector<std::int16_t>& scratch, std::vector<std::uint8_t>& packed) {
    scratch.assign(std::size_t(tile) * std::size_t(tile), 0);
    const int cols = std::min(tile, n - col0);
    for (int r = 0; r < rows; ++r)
        std::copy_n(heights.data() + std::size_t(r) * std::size_t(n) + std::size_t(col0), cols,
                    scratch.data() + std::size_t(r) * std::size_t(tile));
    for (int r = 0; r < tile; ++r) {
        auto* row = reinterpret_cast<std::uint16_t*>(scratch.data() + std::size_t(r) * std::size_t(tile));
        for (int c = tile - 1; c > 0; --c) row[c] = std::uint16_t(row[c] - row[c - 1]);
    }
    const std::size_t bytes = scratch.size() * sizeof(std::int16_t);
    packed.resize(raster::zlib_bound(bytes));
    const std::size_t size =
        raster::zlib_compress(kDeflater, kDeflateLevel, reinterpret_cast<const std::uint8_t*>(scratch.data()), bytes,
                              packed.data(), packed.size());
    if (size == 0) throw std::runtime_error("bench dem: deflate failed");
    packed.resize(size);
}

void set_tags(TIFF* tif, const BenchDemArgs& a, const std::string& path) {
    TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, std::uint32_t(a.n));
    TIFFSetField(tif, TIFFTAG_IMAGELENGTH, std::uint32_t(a.n));
    TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, 16);
    TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_INT);
    TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, 1);
    TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
    TIFFSetField(tif, TIFFTAG_TILEWIDTH, std::uint32_t(a.tile));
    TIFFSetField(tif, TIFFTAG_TILELENGTH, std::uint32_t(a.tile));
    TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
    TIFFSetField(tif, TIFFTAG_PREDICTOR, PREDICTOR_HORIZONTAL);
    TIFFSetField(tif, TIFFTAG_GDAL_NODATA, std::to_string(kNodata).c_str());
    raster::write_geotiff_georef(tif, synthetic_georef(a.n), path);
}

Extremes write_dem(const std::filesystem::path& tmp, const BenchDemArgs& a) {
    const int n = a.n, tile = a.tile, workers = thread_count(a.threads);
    const int across = (n + tile - 1) / tile, bands = across;  // tiles a row, bands of tile rows
    // BigTIFF once the raw grid passes 3 GiB: deflate may not bring it under classic TIFF's 4 GiB.
    const bool big = std::uint64_t(n) * std::uint64_t(n) * 2 > (std::uint64_t(3) << 30);
    raster::TiffFile file(tmp, big ? "w8" : "w");
    TIFF* tif = file.get();
    set_tags(tif, a, tmp.string());
    std::vector<float> z(std::size_t(n) * std::size_t(tile));
    std::vector<std::int16_t> heights(z.size());
    std::vector<std::vector<std::int16_t>> scratch(static_cast<std::size_t>(workers));
    std::vector<std::vector<std::uint8_t>> packed(static_cast<std::size_t>(across));
    Extremes extremes;
    ProgressBar bar("bench dem", std::uint64_t(n), "rows");
    for (int band = 0; band < bands; ++band) {
        const int row0 = band * tile, rows = std::min(tile, n - row0);
        z.resize(std::size_t(n) * std::size_t(rows));
        synthetic_rows(n, row0, rows, z, workers);
        heights.resize(z.size());
        for (std::size_t i = 0; i < z.size(); ++i) heights[i] = std::int16_t(std::lround(z[i]));
        parallel_for(across, workers, [&](int t, int w) {
            encode_tile(heights, n, rows, t * tile, tile, scratch[std::size_t(w)], packed[std::size_t(t)]);
        });
        for (std::int16_t h : heights) extremes.lo = std::min(extremes.lo, h), extremes.hi = std::max(extremes.hi, h);
        for (int t = 0; t < across; ++t) {
            auto& p = packed[std::size_t(t)];
            if (TIFFWriteRawTile(tif, ttile_t(band * across + t), p.data(), tmsize_t(p.size())) < 0)
                throw input_error(a.out, "writing TIFF failed: " + file.last_error());
        }
        bar.advance(std::uint64_t(rows));
    }
    bar.finish();
    file.close();
    return extremes;
}

void run_bench_dem(const BenchDemArgs& a) {
    if (a.n == -1)
        throw InputError("bench dem: give the side N (" + std::to_string(kMinSide) + ".." + std::to_string(kMaxSide) +
                         " texels)");
    if (a.n < kMinSide || a.n > kMaxSide)
        throw InputError("bench dem " + std::to_string(a.n) + ": give a side N of " + std::to_string(kMinSide) + ".." +
                         std::to_string(kMaxSide) + " texels");
    if (a.out.empty()) throw InputError("bench dem: give --out FILE.tif");
    if (a.tile < 16 || a.tile > 4096 || a.tile % 16 != 0)
        throw InputError("--tile " + std::to_string(a.tile) + ": give a multiple of 16 in 16..4096 (TIFF tiles)");
    if (a.threads < 0) throw InputError("--threads must be >= 0 (0 = one per core)");
    IoPlan plan;
    plan.output("--out", a.out, {".tif", ".tiff"});
    plan.check();
    const Stopwatch watch;
    Extremes e;
    write_atomically(a.out, [&](const std::filesystem::path& tmp) { e = write_dem(tmp, a); });
    const std::uint64_t bytes = std::filesystem::file_size(a.out);
    std::printf("wrote %s: %dx%d int16 texels, heights %d..%d m, %s (%.2f bytes a texel) in %.1f s\n", a.out.c_str(),
                a.n, a.n, int(e.lo), int(e.hi), format_bytes(bytes).c_str(),
                double(bytes) / (double(a.n) * double(a.n)), watch.seconds());
}

}  // namespace

void add_bench_dem_command(CLI::App& bench) {
    auto a = std::make_shared<BenchDemArgs>();
    CLI::App* cmd = bench.add_subcommand(
        "dem",
        "Write the synthetic mosaic of `bench tiles synthetic:N` as an N x N int16 GeoTIFF, band by band "
        "(a DEM larger than memory for `fly --stream`)");
    // Range and presence are checked in run_bench_dem, for one line naming the problem.
    cmd->add_option("N", a->n, "Side in texels (2..200000; 1 arc-second cells from 41 N 40 E)");
    cmd->add_option("--out", a->out, "The GeoTIFF to write (.tif)");
    cmd->add_option("--tile", a->tile, "Tile side in texels (a multiple of 16)")->capture_default_str();
    cmd->add_option("--threads", a->threads, "Worker threads (0 = one per core)")->capture_default_str();
    cmd->callback([a] { run_bench_dem(*a); });
}

}  // namespace ts::app
