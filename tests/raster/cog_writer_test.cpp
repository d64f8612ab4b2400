// core/raster/cog_writer: the COG re-layout keeps every tag and tile byte for byte (libtiff reads
// the result back: the full resolution equals the input, each overview the 2x2 alpha-weighted
// average of the level above), the IFDs precede every tile, the tiles run from the smallest
// overview to the full resolution, each behind its size leader and before its trailer.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include <gtest/gtest.h>
#include <tiffio.h>

#include "core/raster/cog_writer.hpp"
#include "core/raster/tiff_file.hpp"

namespace ts::raster {
namespace {
namespace fs = std::filesystem;

geo::Georef lonlat_georef(int w, int h) {
    geo::GeoTransform t;
    t.x0 = 5.0, t.dx_col = 0.001, t.dx_row = 0, t.y0 = 46.0, t.dy_col = 0, t.dy_row = -0.001;
    return geo::Georef(w, h, t, geo::Crs::wgs84(), true);
}

// Every directory of a tiled TIFF, read through libtiff: (width, height, RGBA pixels).
struct Level {
    int width = 0, height = 0;
    std::vector<std::uint8_t> px;
};
std::vector<Level> read_levels(const fs::path& p, int channels) {
    register_tiff_tags();
    std::vector<Level> out;
    TIFF* tif = TIFFOpen(p.c_str(), "r");
    if (!tif) return out;
    do {
        Level l;
        std::uint32_t w = 0, h = 0, tw = 0, th = 0;
        TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &w);
        TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &h);
        TIFFGetField(tif, TIFFTAG_TILEWIDTH, &tw);
        TIFFGetField(tif, TIFFTAG_TILELENGTH, &th);
        l.width = int(w), l.height = int(h);
        l.px.resize(std::size_t(w) * h * std::size_t(channels));
        std::vector<std::uint8_t> tile(TIFFTileSize(tif));
        for (std::uint32_t r0 = 0; r0 < h; r0 += th)
            for (std::uint32_t c0 = 0; c0 < w; c0 += tw) {
                TIFFReadTile(tif, tile.data(), c0, r0, 0, 0);
                for (std::uint32_t r = r0; r < std::min(h, r0 + th); ++r)
                    for (std::uint32_t c = c0; c < std::min(w, c0 + tw); ++c)
                        for (int k = 0; k < channels; ++k)
                            l.px[(std::size_t(r) * w + c) * std::size_t(channels) + std::size_t(k)] =
                                tile[(std::size_t(r - r0) * tw + (c - c0)) * std::size_t(channels) + std::size_t(k)];
            }
        out.push_back(std::move(l));
    } while (TIFFReadDirectory(tif));
    TIFFClose(tif);
    return out;
}

TEST(CogWriter, LevelsRoundTripAndOverviewsAverageWithAlpha) {
    const int w = 700, h = 300, ch = 4;
    std::vector<std::uint8_t> px(std::size_t(w) * h * ch);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            std::uint8_t* p = &px[(std::size_t(r) * w + c) * ch];
            p[0] = std::uint8_t(c * 7 + r), p[1] = std::uint8_t(r * 3), p[2] = std::uint8_t((c ^ r) & 0xff);
            p[3] = (c + r) % 5 == 0 ? 0 : 255;  // scattered transparent pixels
        }
    const fs::path dir = fs::temp_directory_path() / "terrashade_cog_test";
    fs::create_directories(dir);
    const fs::path file = dir / "x.tif";
    write_cog_u8(file, w, h, ch, px.data(), lonlat_georef(w, h));
    const auto levels = read_levels(file, ch);
    const auto sizes = cog_overview_sizes(w, h);
    ASSERT_EQ(sizes.size(), 2u);  // 350x150, 175x75
    ASSERT_EQ(levels.size(), 1 + sizes.size());
    EXPECT_EQ(levels[0].px, px);
    for (std::size_t i = 1; i < levels.size(); ++i) {
        const Level &up = levels[i - 1], &l = levels[i];
        ASSERT_EQ(l.width, sizes[i - 1].first);
        ASSERT_EQ(l.height, sizes[i - 1].second);
        long worst = 0;
        for (int r = 0; r < l.height; ++r)
            for (int c = 0; c < l.width; ++c) {
                double sum[3] = {0, 0, 0}, wsum = 0, asum = 0;
                int n = 0;
                for (int dr = 0; dr < 2; ++dr)
                    for (int dc = 0; dc < 2; ++dc) {
                        if (2 * r + dr >= up.height || 2 * c + dc >= up.width) continue;
                        const std::uint8_t* p = &up.px[(std::size_t(2 * r + dr) * up.width + 2 * c + dc) * ch];
                        for (int k = 0; k < 3; ++k) sum[k] += p[3] * double(p[k]);
                        wsum += p[3], asum += p[3], ++n;
                    }
                const std::uint8_t* q = &l.px[(std::size_t(r) * l.width + c) * ch];
                for (int k = 0; k < 3; ++k)
                    if (wsum > 0) worst = std::max(worst, long(std::abs(q[k] - sum[k] / wsum) + 0.5));
                worst = std::max(worst, long(std::abs(q[3] - asum / n) + 0.5));
            }
        EXPECT_LE(worst, 1) << "overview " << i;
    }

    // Layout: IFD chain before the first tile; tiles of the last (smallest) level first.
    std::ifstream in(file, std::ios::binary);
    const std::vector<std::uint8_t> b{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::string ghost(b.begin() + 8, b.begin() + 8 + 43);
    EXPECT_EQ(ghost.rfind("GDAL_STRUCTURAL_METADATA_SIZE=", 0), 0u) << ghost;
    register_tiff_tags();
    TIFF* tif = TIFFOpen(file.c_str(), "r");
    ASSERT_NE(tif, nullptr);
    std::vector<std::uint64_t> ifd_offsets, first_tile, last_tile_end;
    do {
        ifd_offsets.push_back(TIFFCurrentDirOffset(tif));
        std::uint64_t lo = ~0ull, hi = 0;
        for (ttile_t t = 0; t < TIFFNumberOfTiles(tif); ++t) {
            const std::uint64_t off = TIFFGetStrileOffset(tif, t), n = TIFFGetStrileByteCount(tif, t);
            lo = std::min(lo, off), hi = std::max(hi, off + n);
            // Leader: the size; trailer: the last 4 bytes again.
            const std::uint32_t leader = b[off - 4] | b[off - 3] << 8 | b[off - 2] << 16 | std::uint32_t(b[off - 1]) << 24;
            EXPECT_EQ(leader, n);
            EXPECT_TRUE(std::equal(b.begin() + std::ptrdiff_t(off + n - 4), b.begin() + std::ptrdiff_t(off + n),
                                   b.begin() + std::ptrdiff_t(off + n)));
        }
        first_tile.push_back(lo), last_tile_end.push_back(hi);
    } while (TIFFReadDirectory(tif));
    TIFFClose(tif);
    for (std::size_t i = 1; i < ifd_offsets.size(); ++i) EXPECT_GT(ifd_offsets[i], ifd_offsets[i - 1]);
    for (std::size_t i = 0; i < first_tile.size(); ++i) EXPECT_GT(first_tile[i], ifd_offsets.back());
    for (std::size_t i = 0; i + 1 < first_tile.size(); ++i) EXPECT_GT(first_tile[i], last_tile_end[i + 1]);
    EXPECT_EQ(last_tile_end[0] + 4, b.size());
    fs::remove_all(dir);
}

}  // namespace
}  // namespace ts::raster
