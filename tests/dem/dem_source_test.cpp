// DemSource reads every window exactly as read_dem + mosaic decode the whole grid, decodes
// only the blocks a window touches, keeps its cache within budget, and fails on bad input
// with read_dem's and mosaic's messages.
#include <algorithm>
#include <atomic>
#include <climits>
#include <cmath>
#include <fstream>
#include <random>
#include <set>
#include <stdexcept>
#include <thread>

#include <gtest/gtest.h>
#include <xtiffio.h>
#include <zip.h>

#include "core/dem/dem_source.hpp"
#include "core/dem/mosaic.hpp"
#include "core/dem/read_dem.hpp"
#include "core/raster/geotiff_georef.hpp"
#include "core/raster/tiff_file.hpp"
#include "core/util/error.hpp"
#include "tests/dem/dem_test_files.hpp"

using namespace ts::dem;
namespace fs = std::filesystem;

namespace {

fs::path shared(const std::string& name) { return fs::path(TS_SHARED_DATA) / "dem" / name; }

Dem read_whole(const std::vector<fs::path>& paths) {
    std::vector<Dem> parts;
    for (const fs::path& p : paths) parts.push_back(read_dem(p));
    return mosaic(std::move(parts));
}

void expect_same_layout(const DemLayout& l, const Dem& d) {
    EXPECT_EQ(l.width, d.width);
    EXPECT_EQ(l.height, d.height);
    EXPECT_EQ(l.georef.width(), d.georef.width());
    EXPECT_EQ(l.georef.height(), d.georef.height());
    const ts::geo::GeoTransform &a = l.georef.transform(), &b = d.georef.transform();
    EXPECT_EQ(a.x0, b.x0);
    EXPECT_EQ(a.dx_col, b.dx_col);
    EXPECT_EQ(a.dx_row, b.dx_row);
    EXPECT_EQ(a.y0, b.y0);
    EXPECT_EQ(a.dy_col, b.dy_col);
    EXPECT_EQ(a.dy_row, b.dy_row);
    ASSERT_TRUE(l.georef.valid());
    EXPECT_TRUE(l.georef.crs().same_as(d.georef.crs()));
    EXPECT_EQ(l.georef.crs().name(), d.georef.crs().name());
    EXPECT_EQ(l.georef.crs().epsg(), d.georef.crs().epsg());
    EXPECT_EQ(l.georef.pixel_is_area(), d.georef.pixel_is_area());
    EXPECT_EQ(l.vertical_datum, d.vertical_datum);
    EXPECT_EQ(l.source, d.source);
}

struct Window {
    int col0, row0, width, height;
};

// The window read from `source` against the same cells of `whole`: NaN where it is NaN,
// equal heights elsewhere, equal void flags; also read without flags.
::testing::AssertionResult window_matches(const DemSource& source, const Dem& whole, const Window& w) {
    std::vector<float> z, z_only;
    std::vector<std::uint8_t> voids;
    source.read(w.col0, w.row0, w.width, w.height, z, &voids);
    source.read(w.col0, w.row0, w.width, w.height, z_only);
    const std::size_t n = std::size_t(w.width) * std::size_t(w.height);
    const std::string where = " in window " + std::to_string(w.width) + "x" + std::to_string(w.height) + " at (" +
                              std::to_string(w.col0) + ", " + std::to_string(w.row0) + ")";
    if (z.size() != n || voids.size() != n || z_only.size() != n) return ::testing::AssertionFailure() << "wrong size" << where;
    for (int r = 0; r < w.height; ++r)
        for (int c = 0; c < w.width; ++c) {
            const std::size_t i = std::size_t(r) * std::size_t(w.width) + std::size_t(c);
            const float want = whole.at(w.col0 + c, w.row0 + r);
            const bool want_void = whole.is_void(w.col0 + c, w.row0 + r);
            for (float got : {z[i], z_only[i]}) {
                const bool same = std::isnan(want) ? std::isnan(got) : got == want;
                if (!same)
                    return ::testing::AssertionFailure() << "cell (" << w.col0 + c << ", " << w.row0 + r << ") is " << got
                                                         << ", read_dem has " << want << where;
            }
            if ((voids[i] != 0) != want_void)
                return ::testing::AssertionFailure() << "void flag of cell (" << w.col0 + c << ", " << w.row0 + r << ") is "
                                                     << int(voids[i]) << where;
        }
    return ::testing::AssertionSuccess();
}

// The whole grid, strips along each edge, the corner cells, blocks in the corners, and random
// windows of every size (half of them small, as a streamer asks for tiles).
std::vector<Window> windows_for(int w, int h, unsigned seed) {
    std::vector<Window> out = {{0, 0, w, h},     {0, 0, w, 1},         {0, h - 1, w, 1},          {0, 0, 1, h},
                               {w - 1, 0, 1, h}, {0, 0, 1, 1},         {w - 1, 0, 1, 1},          {0, h - 1, 1, 1},
                               {w - 1, h - 1, 1, 1}};
    const int bw = std::min(w, 17), bh = std::min(h, 5);
    out.push_back({w - bw, h - bh, bw, bh});
    out.push_back({0, h - bh, bw, bh});
    out.push_back({w - bw, 0, bw, bh});
    std::mt19937 rng(seed);
    auto below = [&](int n) { return int(rng() % unsigned(n)); };
    for (int k = 0; k < 40; ++k) {
        const bool small = k % 2 == 0;
        const int ww = 1 + below(small ? std::min(w, 64) : w), hh = 1 + below(small ? std::min(h, 64) : h);
        out.push_back({below(w - ww + 1), below(h - hh + 1), ww, hh});
    }
    for (int k = 0; k < 10; ++k) out.push_back({below(w), below(h), 1, 1});
    return out;
}

void expect_every_window_matches(const std::vector<fs::path>& paths, std::size_t cache_bytes = std::size_t(256) << 20) {
    const Dem whole = read_whole(paths);
    const DemSource source(paths, cache_bytes);
    expect_same_layout(source.layout(), whole);
    unsigned seed = 1;
    for (const fs::path& p : paths) seed = seed * 31 + unsigned(p.string().size());
    for (const Window& w : windows_for(whole.width, whole.height, seed)) ASSERT_TRUE(window_matches(source, whole, w));
    EXPECT_LE(source.cached_bytes(), cache_bytes);
    EXPECT_LE(source.peak_cached_bytes(), cache_bytes);
}

// A GeoTIFF written block by block with libtiff: tiles of `block` x `block` cells or strips
// of `block` rows, any compression and predictor; blocks listed in `skip` are never written,
// so they have no bytes (sparse, as GDAL's SPARSE_OK writes them). Without samples, the
// blocks written hold zeros.
struct TiffLayout {
    int width = 0, height = 0;
    int bits = 16, format = SAMPLEFORMAT_INT;
    bool tiled = false;
    int block = 0;
    int compression = COMPRESSION_NONE, predictor = PREDICTOR_NONE;
    std::string nodata;
    std::vector<std::uint32_t> skip;
};

void write_blocks(const fs::path& path, const TiffLayout& s, const std::vector<std::uint8_t>& samples) {
    ts::raster::register_tiff_tags();
    TIFF* tif = XTIFFOpen(path.string().c_str(), "w");
    ASSERT_NE(tif, nullptr);
    const std::size_t size = std::size_t(s.bits / 8);
    TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, std::uint32_t(s.width));
    TIFFSetField(tif, TIFFTAG_IMAGELENGTH, std::uint32_t(s.height));
    TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, s.bits);
    TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, s.format);
    TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, 1);
    TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
    TIFFSetField(tif, TIFFTAG_COMPRESSION, s.compression);
    if (s.predictor != PREDICTOR_NONE) TIFFSetField(tif, TIFFTAG_PREDICTOR, s.predictor);
    if (!s.nodata.empty()) TIFFSetField(tif, TIFFTAG_GDAL_NODATA, s.nodata.c_str());
    const ts::geo::Georef georef(s.width, s.height, {5.0, 1.0 / 3600, 0, 46.0, 0, -1.0 / 3600},
                                 ts::geo::Crs::wgs84(), true);
    ts::raster::write_geotiff_georef(tif, georef, path.string());
    const std::set<std::uint32_t> skip(s.skip.begin(), s.skip.end());
    auto skipped = [&](std::uint32_t i) { return skip.count(i) != 0; };
    const std::size_t row_bytes = std::size_t(s.width) * size;
    if (s.tiled) {
        TIFFSetField(tif, TIFFTAG_TILEWIDTH, std::uint32_t(s.block));
        TIFFSetField(tif, TIFFTAG_TILELENGTH, std::uint32_t(s.block));
        std::vector<std::uint8_t> tile(std::size_t(s.block) * std::size_t(s.block) * size);
        for (int ty = 0; ty < s.height; ty += s.block)
            for (int tx = 0; tx < s.width; tx += s.block) {
                const std::uint32_t i = TIFFComputeTile(tif, std::uint32_t(tx), std::uint32_t(ty), 0, 0);
                if (skipped(i)) continue;
                std::fill(tile.begin(), tile.end(), 0);
                for (int r = 0; !samples.empty() && r < s.block && ty + r < s.height; ++r) {
                    const int cols = std::min(s.block, s.width - tx);
                    std::memcpy(&tile[std::size_t(r) * std::size_t(s.block) * size],
                                &samples[std::size_t(ty + r) * row_bytes + std::size_t(tx) * size], std::size_t(cols) * size);
                }
                ASSERT_GE(TIFFWriteEncodedTile(tif, i, tile.data(), tmsize_t(tile.size())), 0);
            }
    } else {
        TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, std::uint32_t(s.block));
        for (int y = 0, i = 0; y < s.height; y += s.block, ++i) {
            if (skipped(std::uint32_t(i))) continue;
            const std::size_t bytes = std::size_t(std::min(s.block, s.height - y)) * row_bytes;
            std::vector<std::uint8_t> strip(bytes, 0);
            if (!samples.empty()) std::memcpy(strip.data(), &samples[std::size_t(y) * row_bytes], bytes);
            ASSERT_GE(TIFFWriteEncodedStrip(tif, std::uint32_t(i), strip.data(), tmsize_t(bytes)), 0);
        }
    }
    XTIFFClose(tif);
}

// Heights with structure at every scale, so a misplaced block or row shows.
float height_at(int c, int r) { return float((c * 7 + r * 13) % 3001) - 100.0f + 0.25f * float((c + r) % 4); }

// A striped int16 file of width x height cells, `rows` rows per strip, deflate.
fs::path striped_int16(const fs::path& dir, int width, int height, int rows) {
    std::vector<std::int16_t> v(std::size_t(width) * std::size_t(height));
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c) v[std::size_t(r) * std::size_t(width) + std::size_t(c)] = std::int16_t(height_at(c, r));
    TiffLayout s;
    s.width = width;
    s.height = height;
    s.block = rows;
    s.compression = COMPRESSION_ADOBE_DEFLATE;
    const fs::path p = dir / ("striped_" + std::to_string(width) + "x" + std::to_string(height) + ".tif");
    write_blocks(p, s, test_files::as_bytes(v));
    return p;
}

// A tiled float32 file, `tile` x `tile` tiles, deflate.
fs::path tiled_float(const fs::path& dir, int width, int height, int tile) {
    std::vector<float> v(std::size_t(width) * std::size_t(height));
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c) v[std::size_t(r) * std::size_t(width) + std::size_t(c)] = height_at(c, r);
    TiffLayout s;
    s.width = width;
    s.height = height;
    s.bits = 32;
    s.format = SAMPLEFORMAT_IEEEFP;
    s.tiled = true;
    s.block = tile;
    s.compression = COMPRESSION_ADOBE_DEFLATE;
    const fs::path p = dir / ("tiled_" + std::to_string(width) + "x" + std::to_string(height) + ".tif");
    write_blocks(p, s, test_files::as_bytes(v));
    return p;
}

template <typename Fn>
std::string input_error_of(Fn fn) {
    try {
        fn();
    } catch (const ts::InputError& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "threw a non-InputError: " << e.what();
        return {};
    }
    ADD_FAILURE() << "no error";
    return {};
}

// DemSource fails on `paths` with read_dem + mosaic's message, one line naming the file.
void expect_same_error(const std::vector<fs::path>& paths, const std::string& problem) {
    const std::string streamed = input_error_of([&] { DemSource source(paths); });
    const std::string whole = input_error_of([&] { read_whole(paths); });
    EXPECT_EQ(streamed, whole);
    EXPECT_NE(streamed.find(problem), std::string::npos) << streamed;
    EXPECT_EQ(streamed.find('\n'), std::string::npos) << streamed;
}

}  // namespace

TEST(DemSource, SharedDemsMatchReadDemInEveryWindow) {
    const std::vector<std::vector<fs::path>> cases = {
        {shared("N00E010.hgt")},
        {shared("N00E011.hgt.zip")},
        {shared("N00E010.hgt"), shared("N00E011.hgt.zip")},
        {shared("srtm3_N39E040_1000px.tif")},
        {shared("copernicus_N45E005_grenoble_500px.tif")},
        {shared("etopo1_global_1deg.tif")},
        {shared("nodata_3x3.tif")},
    };
    for (const auto& paths : cases) {
        SCOPED_TRACE(paths.front().filename().string() + (paths.size() > 1 ? " + ..." : ""));
        expect_every_window_matches(paths);
    }
}

TEST(DemSource, MosaicSeamAndUncoveredCellsMatch) {
    // Across the shared column of two SRTM tiles, in either order.
    const std::vector<fs::path> we = {shared("N00E010.hgt"), shared("N00E011.hgt.zip")};
    const std::vector<fs::path> ew = {shared("N00E011.hgt.zip"), shared("N00E010.hgt")};
    for (const auto& paths : {we, ew}) {
        const Dem whole = read_whole(paths);
        const DemSource source(paths);
        expect_same_layout(source.layout(), whole);
        EXPECT_EQ(source.layout().width, 2401);
        for (const Window& w : {Window{1190, 300, 21, 9}, Window{1200, 0, 1, 1201}, Window{1199, 1195, 3, 6}})
            EXPECT_TRUE(window_matches(source, whole, w));
    }
    // Two tiles diagonal to each other: half the mosaic is covered by neither.
    const fs::path dir = test_files::fresh_dir("source_diagonal");
    test_files::write_bytes(dir / "N00E010.hgt", test_files::synthetic_hgt({{5, 5}, {1200, 0}}));
    test_files::write_bytes(dir / "N01E011.hgt", test_files::synthetic_hgt({{0, 1200}}));
    expect_every_window_matches({dir / "N00E010.hgt", dir / "N01E011.hgt"});
}

TEST(DemSource, SharedCellsKeepTheFirstValidHeight) {
    // West's column 1200 is east's column 0, with other heights there: west's win, except
    // where west is void; a void in east hides nothing.
    const fs::path dir = test_files::fresh_dir("source_overlap");
    std::string east = test_files::synthetic_hgt({{0, 20}, {0, 30}});
    for (std::size_t i = 0; i < east.size(); i += 2)
        if (east[i] != char(0x80)) east[i] = char(east[i] + 0x10);  // + 4096 m, voids kept
    test_files::write_bytes(dir / "N00E010.hgt", test_files::synthetic_hgt({{1200, 10}, {1200, 30}}));
    test_files::write_bytes(dir / "N00E011.hgt", east);
    const std::vector<fs::path> paths = {dir / "N00E010.hgt", dir / "N00E011.hgt"};
    const Dem whole = read_whole(paths);
    const DemSource source(paths);
    std::vector<float> z;
    std::vector<std::uint8_t> voids;
    source.read(1200, 0, 1, 40, z, &voids);
    EXPECT_EQ(z[0], 1200.0f);        // west's
    EXPECT_EQ(z[10], 4096.0f + 10);  // west void: east's
    EXPECT_EQ(z[20], 1220.0f);       // east void: west's
    EXPECT_TRUE(std::isnan(z[30]));  // void in both
    EXPECT_EQ(voids[30], 1);
    EXPECT_EQ(voids[10], 0);
    for (const Window& w : {Window{1200, 0, 1, 1201}, Window{1190, 0, 20, 50}}) EXPECT_TRUE(window_matches(source, whole, w));
}

TEST(DemSource, TiledAndStripedGeoTiffsMatch) {
    const fs::path dir = test_files::fresh_dir("source_layouts");
    const int w = 301, h = 203;  // no multiple of any block size
    // float32, 64x64 tiles, deflate with the floating-point predictor; nodata, NaN and +Inf
    // cells, and one tile never written (sparse: voids, as the file has a nodata value).
    std::vector<float> f(std::size_t(w * h));
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) f[std::size_t(r * w + c)] = height_at(c, r);
    f[7] = -9999.0f;
    f[std::size_t(150 * w + 299)] = std::numeric_limits<float>::quiet_NaN();
    f[std::size_t(202 * w + 300)] = std::numeric_limits<float>::infinity();
    TiffLayout tiled;
    tiled.width = w;
    tiled.height = h;
    tiled.bits = 32;
    tiled.format = SAMPLEFORMAT_IEEEFP;
    tiled.tiled = true;
    tiled.block = 64;
    tiled.compression = COMPRESSION_ADOBE_DEFLATE;
    tiled.predictor = PREDICTOR_FLOATINGPOINT;
    tiled.nodata = "-9999";
    tiled.skip = {6};  // second row of tiles, second tile
    write_blocks(dir / "tiled.tif", tiled, test_files::as_bytes(f));
    ASSERT_EQ(test_files::sparse_blocks(dir / "tiled.tif"), 1);

    // int16, 7 rows per strip (the last one short), LZW with the horizontal predictor; one
    // strip never written and no nodata value (sparse: zeros).
    std::vector<std::int16_t> s(f.size());
    for (std::size_t i = 0; i < s.size(); ++i) s[i] = std::int16_t(std::isfinite(f[i]) ? f[i] : -32768.0f);
    TiffLayout striped;
    striped.width = w;
    striped.height = h;
    striped.block = 7;
    striped.compression = COMPRESSION_LZW;
    striped.predictor = PREDICTOR_HORIZONTAL;
    striped.skip = {3};
    write_blocks(dir / "striped.tif", striped, test_files::as_bytes(s));
    ASSERT_EQ(test_files::sparse_blocks(dir / "striped.tif"), 1);

    // uint8, one row per strip, uncompressed, nodata 0.
    std::vector<std::uint8_t> u(f.size());
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = std::uint8_t(i % 251);
    TiffLayout rows;
    rows.width = w;
    rows.height = h;
    rows.bits = 8;
    rows.format = SAMPLEFORMAT_UINT;
    rows.block = 1;
    rows.nodata = "0";
    write_blocks(dir / "rows.tif", rows, u);

    for (const char* name : {"tiled.tif", "striped.tif", "rows.tif"}) {
        SCOPED_TRACE(name);
        expect_every_window_matches({dir / name});
        expect_every_window_matches({dir / name}, 0);  // nothing kept: every read decodes again
    }
    const Dem t = read_dem(dir / "tiled.tif");
    EXPECT_TRUE(t.is_void(64 + 5, 64 + 5));  // in the sparse tile
    const Dem st = read_dem(dir / "striped.tif");
    EXPECT_EQ(st.at(10, 3 * 7 + 1), 0.0f);  // in the sparse strip
    EXPECT_FALSE(st.is_void(10, 3 * 7 + 1));
}

TEST(DemSource, ReadsOnlyTheStripsAWindowNeeds) {
    const fs::path dir = test_files::fresh_dir("source_strips");
    const int w = 4000, h = 1000, rows = 8;  // 125 strips of 64 KB decoded, 8 MB in all
    const fs::path p = striped_int16(dir, w, h, rows);
    const std::size_t strip_bytes = std::size_t(w) * rows * 2, whole_bytes = std::size_t(w) * h * 2;
    const Dem whole = read_dem(p);

    const DemSource source({p});
    EXPECT_EQ(source.decoded_blocks(), 0u);  // opening reads the header only
    EXPECT_EQ(source.cached_bytes(), 0u);
    ASSERT_TRUE(window_matches(source, whole, {1000, 100, 16, 16}));  // rows 100..115: strips 12..14
    EXPECT_EQ(source.decoded_blocks(), 3u);
    EXPECT_EQ(source.cached_bytes(), 3 * strip_bytes);
    ASSERT_TRUE(window_matches(source, whole, {3000, 97, 40, 8}));  // strips 12 and 13 again: cached
    EXPECT_EQ(source.decoded_blocks(), 3u);
    EXPECT_EQ(source.peak_cached_bytes(), 3 * strip_bytes);
    EXPECT_LT(source.peak_cached_bytes(), whole_bytes / 40);
}

TEST(DemSource, ReadsOnlyTheTilesAWindowNeeds) {
    const fs::path dir = test_files::fresh_dir("source_tiles");
    const fs::path p = tiled_float(dir, 1024, 1024, 64);  // 16x16 tiles of 16 KB
    const std::size_t tile_bytes = 64 * 64 * 4;
    const Dem whole = read_dem(p);

    const DemSource source({p});
    ASSERT_TRUE(window_matches(source, whole, {130, 200, 10, 10}));  // inside tile (2, 3)
    EXPECT_EQ(source.decoded_blocks(), 1u);
    ASSERT_TRUE(window_matches(source, whole, {500, 500, 40, 40}));  // tiles (7..8, 7..8)
    EXPECT_EQ(source.decoded_blocks(), 5u);
    ASSERT_TRUE(window_matches(source, whole, {512, 512, 64, 64}));  // tile (8, 8): cached
    EXPECT_EQ(source.decoded_blocks(), 5u);
    EXPECT_EQ(source.cached_bytes(), 5 * tile_bytes);
}

TEST(DemSource, CacheEvictsTheLeastRecentlyUsedWithinItsBudget) {
    const fs::path dir = test_files::fresh_dir("source_lru");
    const fs::path p = tiled_float(dir, 256, 64, 64);  // 4 tiles in a row
    const std::size_t tile_bytes = 64 * 64 * 4;
    const Dem whole = read_dem(p);
    const DemSource source({p}, 3 * tile_bytes);
    auto tile = [&](int k) { return Window{64 * k + 3, 3, 5, 5}; };

    for (int k : {0, 1, 2}) ASSERT_TRUE(window_matches(source, whole, tile(k)));
    EXPECT_EQ(source.decoded_blocks(), 3u);
    ASSERT_TRUE(window_matches(source, whole, tile(0)));  // a hit, and now the most recent
    EXPECT_EQ(source.decoded_blocks(), 3u);
    ASSERT_TRUE(window_matches(source, whole, tile(3)));  // evicts tile 1, the least recent
    EXPECT_EQ(source.decoded_blocks(), 4u);
    EXPECT_EQ(source.cached_bytes(), 3 * tile_bytes);
    ASSERT_TRUE(window_matches(source, whole, tile(0)));
    ASSERT_TRUE(window_matches(source, whole, tile(2)));
    EXPECT_EQ(source.decoded_blocks(), 4u);
    ASSERT_TRUE(window_matches(source, whole, tile(1)));  // was evicted
    EXPECT_EQ(source.decoded_blocks(), 5u);

    // The whole grid through a budget smaller than it: correct, and the budget holds.
    ASSERT_TRUE(window_matches(source, whole, {0, 0, 256, 64}));
    EXPECT_LE(source.cached_bytes(), 3 * tile_bytes);
    EXPECT_EQ(source.peak_cached_bytes(), 3 * tile_bytes);
}

TEST(DemSource, ZipEntryIsInflatedOnceAndKeptInTheCache) {
    const fs::path zip = shared("N00E011.hgt.zip");
    const Dem whole = read_dem(zip);
    {
        const DemSource source({zip});
        EXPECT_EQ(source.decoded_blocks(), 0u);  // the zip's directory only
        ASSERT_TRUE(window_matches(source, whole, {0, 0, 10, 10}));
        ASSERT_TRUE(window_matches(source, whole, {1000, 1100, 201, 101}));
        EXPECT_EQ(source.decoded_blocks(), 1u);
        EXPECT_EQ(source.cached_bytes(), 2884802u);
    }
    {
        // A budget below the entry: read correctly, inflated for every read, never kept.
        const DemSource source({zip}, 1 << 20);
        ASSERT_TRUE(window_matches(source, whole, {0, 0, 10, 10}));  // two reads each
        ASSERT_TRUE(window_matches(source, whole, {5, 5, 1, 1}));
        EXPECT_EQ(source.decoded_blocks(), 4u);
        EXPECT_EQ(source.cached_bytes(), 0u);
        EXPECT_EQ(source.peak_cached_bytes(), 0u);
    }
}

TEST(DemSource, ConcurrentReadsMatch) {
    const fs::path dir = test_files::fresh_dir("source_threads");
    const std::vector<std::vector<fs::path>> cases = {
        {shared("N00E010.hgt"), shared("N00E011.hgt.zip")},
        {tiled_float(dir, 700, 500, 64)},
        {striped_int16(dir, 700, 500, 9)},
    };
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const std::vector<fs::path>& paths = cases[k];
        const Dem whole = read_whole(paths);
        // The mosaic keeps its zip entry; the others a few blocks, so threads evict what others read.
        const DemSource source(paths, k == 0 ? std::size_t(4) << 20 : std::size_t(64 * 64 * 4 * 3));
        std::atomic<int> failures{0};
        std::vector<std::thread> threads;
        for (unsigned t = 0; t < 4; ++t)
            threads.emplace_back([&, t] {
                for (const Window& w : windows_for(whole.width, whole.height, 100 + t))
                    if (!window_matches(source, whole, w)) ++failures;
            });
        for (std::thread& t : threads) t.join();
        EXPECT_EQ(failures.load(), 0) << paths.front();
    }
}

TEST(DemSource, BadInputFailsAsReadDemAndMosaicDo) {
    const fs::path dir = test_files::fresh_dir("source_bad");
    const std::string tile = test_files::synthetic_hgt();

    expect_same_error({dir / "N00E010.hgt"}, "no such file");
    test_files::write_bytes(dir / "N01E010.hgt", tile.substr(0, tile.size() / 2));
    expect_same_error({dir / "N01E010.hgt"}, "truncated");
    test_files::write_bytes(dir / "tile.hgt", tile);
    expect_same_error({dir / "tile.hgt"}, "south-west corner");
    test_files::write_bytes(dir / "empty.tif", "");
    expect_same_error({dir / "empty.tif"}, "empty file");
    test_files::write_zip(dir / "N00E012.hgt.zip", "readme.txt", "no tile");
    expect_same_error({dir / "N00E012.hgt.zip"}, "holds no .hgt");
    test_files::write_zip(dir / "N00E013.hgt.zip", "N00E013.hgt", tile.substr(0, 1000));
    expect_same_error({dir / "N00E013.hgt.zip"}, "truncated?");
    test_files::write_bytes(dir / "N00E014.hgt", tile);
    expect_same_error({dir / "N00E014.hgt", dir / "missing.tif"}, "no such file");  // the second file
    EXPECT_THROW(DemSource({}), ts::InputError);

    // Mosaics of files that do not share one grid.
    test_files::TiffSpec spec;  // 4x3 cells of 0.25 degrees at (10, 1)
    const auto cells = test_files::as_bytes(std::vector<std::int16_t>(12, 5));
    test_files::write_tiff(dir / "a.tif", spec, cells);
    test_files::TiffSpec coarse = spec;
    coarse.cell = 0.5;
    test_files::write_tiff(dir / "coarse.tif", coarse, cells);
    test_files::TiffSpec shifted = spec;
    shifted.x0 = 11.125;
    test_files::write_tiff(dir / "shifted.tif", shifted, cells);
    test_files::TiffSpec utm = spec;
    utm.epsg = 32633;
    utm.geographic = false;
    utm.x0 = 500000;
    utm.y0 = 100000;
    utm.cell = 30;
    test_files::write_tiff(dir / "utm.tif", utm, cells);
    expect_same_error({dir / "a.tif", dir / "coarse.tif"}, "cell size differs");
    expect_same_error({dir / "a.tif", dir / "shifted.tif"}, "not aligned");
    expect_same_error({dir / "a.tif", dir / "utm.tif"}, "reproject");
    expect_same_error({dir / "a.tif", dir / "N00E014.hgt"}, "cell size differs");
}

TEST(DemSource, WindowsOutsideTheGridAreRefused) {
    const DemSource source({shared("nodata_3x3.tif")});
    std::vector<float> z;
    std::vector<std::uint8_t> voids;
    for (const Window& w : {Window{-1, 0, 1, 1}, Window{0, -1, 1, 1}, Window{0, 0, 4, 1}, Window{0, 0, 1, 4}, Window{3, 0, 1, 1},
                            Window{2, 2, 2, 1}, Window{0, 0, -1, 1}, Window{INT_MAX, 0, INT_MAX, 1},
                            Window{1, 1, INT_MAX, INT_MAX}})
        EXPECT_THROW(source.read(w.col0, w.row0, w.width, w.height, z, &voids), std::invalid_argument)
            << w.col0 << "," << w.row0 << " " << w.width << "x" << w.height;
    source.read(3, 3, 0, 0, z, &voids);  // empty, at the far corner: nothing to read
    EXPECT_TRUE(z.empty());
    EXPECT_TRUE(voids.empty());
}

TEST(DemSource, FilesCutShortAfterOpeningFailCleanly) {
    const fs::path dir = test_files::fresh_dir("source_cut");
    const std::string tile = test_files::synthetic_hgt();
    test_files::write_bytes(dir / "N00E010.hgt", tile);
    const fs::path tif = striped_int16(dir, 500, 400, 10);
    const DemSource hgt({dir / "N00E010.hgt"});
    const DemSource tiff({tif}, 0);
    std::vector<float> z;
    hgt.read(0, 0, 10, 10, z);
    tiff.read(0, 0, 10, 10, z);

    fs::resize_file(dir / "N00E010.hgt", tile.size() / 2);
    EXPECT_NE(input_error_of([&] { hgt.read(0, 1100, 10, 10, z); }).find("truncated while being read"), std::string::npos);
    hgt.read(0, 0, 10, 10, z);  // what is still there reads
    EXPECT_EQ(z[11], 2.0f);

    fs::resize_file(tif, fs::file_size(tif) / 2);
    const std::string cut = input_error_of([&] { tiff.read(0, 390, 500, 10, z); });
    EXPECT_EQ(cut.rfind(tif.string() + ": ", 0), 0u) << cut;
}

TEST(DemSource, StreamsGridsLargerThanAWholeDemMayHold) {
    // 50000x50000 cells (2.5e9, past read_dem's 2^31) in 256x256 tiles: the first of zeros,
    // the rest sparse with a nodata value. A file of a few hundred KB, readable by windows only.
    const fs::path dir = test_files::fresh_dir("source_huge");
    TiffLayout s;
    s.width = s.height = 50000;
    s.tiled = true;
    s.block = 256;
    s.compression = COMPRESSION_ADOBE_DEFLATE;
    s.nodata = "-32768";
    for (std::uint32_t i = 1; i < 196 * 196; ++i) s.skip.push_back(i);
    write_blocks(dir / "huge.tif", s, {});
    ASSERT_LT(fs::file_size(dir / "huge.tif"), 1u << 20);
    EXPECT_NE(input_error_of([&] { read_dem(dir / "huge.tif"); }).find("raster too large"), std::string::npos);

    const DemSource source({dir / "huge.tif"});
    EXPECT_EQ(source.layout().width, 50000);
    EXPECT_EQ(source.layout().height, 50000);
    std::vector<float> z;
    std::vector<std::uint8_t> voids;
    source.read(49990, 49990, 10, 10, z, &voids);
    EXPECT_TRUE(std::all_of(z.begin(), z.end(), [](float v) { return std::isnan(v); }));
    EXPECT_TRUE(std::all_of(voids.begin(), voids.end(), [](std::uint8_t v) { return v == 1; }));
    source.read(250, 250, 10, 10, z, &voids);  // across the written tile and three sparse ones
    EXPECT_EQ(z[0], 0.0f);
    EXPECT_EQ(voids[0], 0);
    EXPECT_TRUE(std::isnan(z[99]));
    EXPECT_EQ(source.decoded_blocks(), 5u);
}
