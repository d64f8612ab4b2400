// The readers refuse a raster before they allocate it when the file cannot hold what its
// header claims or the machine cannot hold the decoded cells; and they read what GDAL writes
// (sparse blocks, +-Inf heights) as voids instead of failing or passing non-heights on.
#include <sys/resource.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>

#include <gtest/gtest.h>
#include <xtiffio.h>

#include "core/dem/read_dem.hpp"
#include "core/raster/tiff_file.hpp"
#include "core/util/error.hpp"
#include "core/util/memory.hpp"
#include "tests/dem/dem_test_files.hpp"

using namespace ts::dem;
namespace fs = std::filesystem;

namespace {

fs::path shared(const std::string& name) { return fs::path(TS_SHARED_DATA) / "dem" / name; }

// The process's peak resident set so far, MB (Linux reports ru_maxrss in KiB). Tests compare
// it with the peak before them: earlier tests in the same process (and ASan's quarantine)
// may already have raised it by a few hundred MB.
long peak_rss_mb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024;
}

// read_dem's one-line InputError for `path`, starting with the path (a zip entry's errors
// name the entry after it); a test failure otherwise.
std::string error_for(const fs::path& path) {
    try {
        read_dem(path);
    } catch (const ts::InputError& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind(path.string(), 0), 0u) << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
        return msg;
    } catch (const std::exception& e) {
        ADD_FAILURE() << path << ": threw a non-InputError: " << e.what();
        return {};
    }
    ADD_FAILURE() << path << ": read without error";
    return {};
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct MemoryCap {
    explicit MemoryCap(std::uint64_t bytes) { ts::set_memory_cap(bytes); }
    ~MemoryCap() { ts::set_memory_cap(0); }
};

int run(const std::string& command) { return std::system(command.c_str()); }

}  // namespace

// A few hundred bytes whose header claims 40000x40000 cells (8 GB decoded): refused from the
// block byte counts alone, so the process never grows towards the claimed size.
TEST(ReaderLimits, LyingHeaderIsRefusedBeforeTheRasterIsAllocated) {
    const long peak_before = peak_rss_mb();
    const fs::path dir = test_files::fresh_dir("lying");
    const std::string payload(16, '\x01');

    test_files::write_lying_tiff(dir / "raw.tif", 40000, 40000, COMPRESSION_NONE, 0, payload);
    ASSERT_LT(fs::file_size(dir / "raw.tif"), 1000u);
    const std::string raw = error_for(dir / "raw.tif");
    EXPECT_TRUE(contains(raw, "truncated")) << raw;

    test_files::write_lying_tiff(dir / "deflate.tif", 40000, 40000, COMPRESSION_ADOBE_DEFLATE, 0, payload);
    const std::string deflate = error_for(dir / "deflate.tif");
    EXPECT_TRUE(contains(deflate, "truncated or corrupt")) << deflate;
    EXPECT_TRUE(contains(deflate, "3.2 GB of samples")) << deflate;

    // 24649 tiles of 256x256, each 16 bytes: every block is in the file, but 16 bytes can
    // decode to 128 KiB neither uncompressed nor through deflate.
    test_files::write_lying_tiff(dir / "tiles_raw.tif", 40000, 40000, COMPRESSION_NONE, 256, payload);
    const std::string tiles_raw = error_for(dir / "tiles_raw.tif");
    EXPECT_TRUE(contains(tiles_raw, "truncated TIFF: uncompressed tile 0 holds 16 bytes")) << tiles_raw;
    test_files::write_lying_tiff(dir / "tiles_lzw.tif", 40000, 40000, COMPRESSION_LZW, 256, payload);
    const std::string tiles_lzw = error_for(dir / "tiles_lzw.tif");
    EXPECT_TRUE(contains(tiles_lzw, "more than 2048:1")) << tiles_lzw;

    EXPECT_LT(peak_rss_mb() - peak_before, 500);
}

// One 16x16 tile whose header is edited to claim 12000x12000 cells: libtiff pads the tile
// offset and byte count lists (one entry each) with zeros, which must not pass for 562499
// sparse tiles of a 720 MB raster. (Past a million tiles libtiff refuses the file itself.)
TEST(ReaderLimits, TooShortBlockListsAreCorruptNotSparse) {
    const long peak_before = peak_rss_mb();
    const fs::path dir = test_files::fresh_dir("short_lists");
    test_files::TiffSpec spec;
    spec.width = spec.height = 16;
    spec.tiled = true;
    spec.nodata = "-32768";
    test_files::write_tiff(dir / "one_tile.tif", spec, test_files::as_bytes(std::vector<std::int16_t>(256, 5)));
    std::ifstream in(dir / "one_tile.tif", std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    ASSERT_TRUE(test_files::patch_tiff_tag(bytes, 256, 12000));
    ASSERT_TRUE(test_files::patch_tiff_tag(bytes, 257, 12000));
    test_files::write_bytes(dir / "claims_more.tif", bytes);
    const std::string msg = error_for(dir / "claims_more.tif");
    EXPECT_TRUE(contains(msg, "corrupt TIFF: its TileOffsets list fewer tiles than the image has")) << msg;
    EXPECT_LT(peak_rss_mb() - peak_before, 500);
}

TEST(ReaderLimits, ARasterLargerThanTheAvailableMemoryIsRefusedWithWhatItNeeds) {
    const MemoryCap cap(2'000'000);
    // 1000 x 1000 cells of a float and a void flag: 5 MB, plus one strip's buffer.
    const std::string tif = error_for(shared("srtm3_N39E040_1000px.tif"));
    EXPECT_TRUE(contains(tif, "decoding 1000x1000 cells needs 5.0 MB of memory but only 2.0 MB is available")) << tif;
    EXPECT_TRUE(contains(tif, "a crop reads the whole raster")) << tif;
    const std::string hgt = error_for(shared("N00E010.hgt"));
    EXPECT_TRUE(contains(hgt, "decoding 1201x1201 cells needs 7.2 MB")) << hgt;
    const std::string zip = error_for(shared("N00E011.hgt.zip"));
    EXPECT_TRUE(contains(zip, "needs 7.2 MB")) << zip;
}

TEST(ReaderLimits, AvailableMemoryComesFromTheSystem) {
    const std::uint64_t available = ts::available_memory();
    EXPECT_GT(available, 16u << 20);  // a machine that runs these tests has more than 16 MB free
    EXPECT_LT(available, std::uint64_t(1) << 50);
    {
        const MemoryCap cap(1000);
        EXPECT_EQ(ts::available_memory(), 1000u);
    }
    EXPECT_EQ(ts::format_bytes(7'500'000'000), "7.5 GB");
    EXPECT_EQ(ts::format_bytes(7'210'000), "7.2 MB");
    EXPECT_EQ(ts::format_bytes(404), "404 bytes");
}

// A 64 x 48 int16 DEM whose nodata (-32768) covers whole 16x16 tiles and 8-row strips, written
// by gdal_translate with SPARSE_OK=TRUE: those blocks are left out of the file (offset and
// byte count 0) and read back as voids; every other cell as written.
TEST(SparseGeoTiff, BlocksGdalLeftOutReadAsVoids) {
    const fs::path dir = test_files::fresh_dir("sparse");
    const int w = 64, h = 48;
    std::vector<std::int16_t> z(std::size_t(w * h));
    auto is_hole = [](int c, int r) { return (c < 32 && r < 16) || r >= 40; };
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r * w + c)] = is_hole(c, r) ? std::int16_t(-32768) : std::int16_t(100 + c + r);
    test_files::TiffSpec spec;
    spec.width = w;
    spec.height = h;
    spec.nodata = "-32768";
    spec.cell = 1.0 / 1200;
    test_files::write_tiff(dir / "source.tif", spec, test_files::as_bytes(z));

    const std::vector<std::pair<std::string, std::string>> layouts = {
        {"tiles.tif", "-co TILED=YES -co BLOCKXSIZE=16 -co BLOCKYSIZE=16"},
        {"tiles_deflate.tif", "-co TILED=YES -co BLOCKXSIZE=16 -co BLOCKYSIZE=16 -co COMPRESS=DEFLATE"},
        {"strips.tif", "-co BLOCKYSIZE=8"},
    };
    for (const auto& [name, options] : layouts) {
        const fs::path out = dir / name;
        ASSERT_EQ(run("gdal_translate -q -co SPARSE_OK=TRUE " + options + " '" + (dir / "source.tif").string() + "' '" +
                      out.string() + "'"),
                  0);
        EXPECT_GT(test_files::sparse_blocks(out), 0) << name << ": gdal_translate wrote no sparse block";
        const Dem d = read_dem(out);
        ASSERT_EQ(d.width, w);
        ASSERT_EQ(d.height, h);
        for (int r = 0; r < h; ++r)
            for (int c = 0; c < w; ++c) {
                ASSERT_EQ(d.is_void(c, r), is_hole(c, r)) << name << " at " << c << "," << r;
                if (!is_hole(c, r)) ASSERT_EQ(d.at(c, r), float(100 + c + r)) << name << " at " << c << "," << r;
                else ASSERT_TRUE(std::isnan(d.at(c, r)));
            }
    }
}

// Without a nodata value GDAL leaves out the all-zero blocks, and specifies that they read
// as 0: heights of 0, not voids.
TEST(SparseGeoTiff, WithoutNodataLeftOutBlocksReadAsZero) {
    const fs::path dir = test_files::fresh_dir("sparse_zero");
    const int w = 32, h = 32;
    std::vector<std::int16_t> z(std::size_t(w * h), 0);
    for (int r = 16; r < h; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r * w + c)] = std::int16_t(7);
    test_files::TiffSpec spec;
    spec.width = w;
    spec.height = h;
    test_files::write_tiff(dir / "source.tif", spec, test_files::as_bytes(z));
    const fs::path out = dir / "sparse.tif";
    ASSERT_EQ(run("gdal_translate -q -co SPARSE_OK=TRUE -co TILED=YES -co BLOCKXSIZE=16 -co BLOCKYSIZE=16 '" +
                  (dir / "source.tif").string() + "' '" + out.string() + "'"),
              0);
    EXPECT_EQ(test_files::sparse_blocks(out), 2);
    const Dem d = read_dem(out);
    EXPECT_EQ(d.void_count(), 0u);
    EXPECT_EQ(d.at(3, 3), 0.0f);
    EXPECT_EQ(d.at(3, 20), 7.0f);
}

// +Inf and -Inf are no heights, like NaN: voids in float32 and float64 files, stripped or
// tiled, as are float64 values beyond float's range. Finite values pass unchanged.
TEST(NonFiniteHeights, InfinitiesBecomeVoids) {
    const fs::path dir = test_files::fresh_dir("inf");
    const double inf = std::numeric_limits<double>::infinity();
    const int w = 20, h = 18;
    std::vector<double> v(std::size_t(w * h));
    for (int i = 0; i < w * h; ++i) v[std::size_t(i)] = 10.0 + i;
    auto is_bad = [](int i) { return i == 0 || i == 7 || i == 55 || i == 359 || i == 200; };
    v[0] = inf;
    v[7] = -inf;
    v[55] = std::numeric_limits<double>::quiet_NaN();
    v[359] = -inf;
    v[200] = 1e300;  // finite as float64, +Inf as float32
    v[201] = -3.0e38;  // within float's range: a (silly) height, kept
    for (bool tiled : {false, true})
        for (int bits : {32, 64}) {
            test_files::TiffSpec spec;
            spec.width = w;
            spec.height = h;
            spec.bits = bits;
            spec.sample_format = 3;
            spec.tiled = tiled;
            const fs::path p = dir / ("f" + std::to_string(bits) + (tiled ? "_tiled" : "") + ".tif");
            if (bits == 32) {
                std::vector<float> f(v.size());
                for (std::size_t i = 0; i < v.size(); ++i) f[i] = std::abs(v[i]) > 3.5e38 ? float(std::copysign(inf, v[i])) : float(v[i]);
                test_files::write_tiff(p, spec, test_files::as_bytes(f));
            } else {
                test_files::write_tiff(p, spec, test_files::as_bytes(v));
            }
            const Dem d = read_dem(p);
            EXPECT_EQ(d.void_count(), 5u) << p;
            for (int i = 0; i < w * h; ++i) {
                const float z = d.z[std::size_t(i)];
                ASSERT_EQ(d.void_mask[std::size_t(i)] != 0, is_bad(i)) << p << " cell " << i;
                if (is_bad(i)) ASSERT_TRUE(std::isnan(z)) << p << " cell " << i;
                else ASSERT_EQ(z, float(v[std::size_t(i)])) << p << " cell " << i;
            }
        }
}
