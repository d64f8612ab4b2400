#include "core/raster/cog_writer.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "core/raster/geotiff_georef.hpp"
#include "core/raster/tiff_file.hpp"
#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"

namespace ts::raster {
namespace {

constexpr std::uint16_t kTagTileOffsets = 324, kTagTileByteCounts = 325;

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> owned;
    const std::uint8_t* data = nullptr;
};

// Each 2x2 block averaged (a last odd row or column from what it has); colours weighted by
// alpha when the last channel is one, so transparent pixels do not darken the edges.
Image halved(const Image& in, int channels) {
    const bool alpha = channels == 2 || channels == 4;
    const int colours = alpha ? channels - 1 : channels;
    Image out;
    out.width = (in.width + 1) / 2, out.height = (in.height + 1) / 2;
    out.owned.resize(std::size_t(out.width) * std::size_t(out.height) * std::size_t(channels));
    for (int r = 0; r < out.height; ++r)
        for (int c = 0; c < out.width; ++c) {
            unsigned sum[4] = {0, 0, 0, 0}, weight = 0, count = 0, alpha_sum = 0;
            for (int dr = 0; dr < 2; ++dr)
                for (int dc = 0; dc < 2; ++dc) {
                    const int sr = 2 * r + dr, sc = 2 * c + dc;
                    if (sr >= in.height || sc >= in.width) continue;
                    const std::uint8_t* p = in.data + (std::size_t(sr) * std::size_t(in.width) + std::size_t(sc)) *
                                                          std::size_t(channels);
                    const unsigned w = alpha ? p[channels - 1] : 1u;
                    for (int k = 0; k < colours; ++k) sum[k] += w * p[k];
                    weight += w, ++count;
                    if (alpha) alpha_sum += p[channels - 1];
                }
            std::uint8_t* q = out.owned.data() + (std::size_t(r) * std::size_t(out.width) + std::size_t(c)) *
                                                     std::size_t(channels);
            for (int k = 0; k < colours; ++k) q[k] = weight ? std::uint8_t((sum[k] + weight / 2) / weight) : 0;
            if (alpha) q[channels - 1] = std::uint8_t((alpha_sum + count / 2) / count);
        }
    out.data = out.owned.data();
    return out;
}

void write_directory(TiffFile& file, const Image& image, int channels, const geo::Georef* georef) {
    TIFF* tif = file.get();
    TIFFSetField(tif, TIFFTAG_SUBFILETYPE, georef ? 0 : FILETYPE_REDUCEDIMAGE);
    TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, std::uint32_t(image.width));
    TIFFSetField(tif, TIFFTAG_IMAGELENGTH, std::uint32_t(image.height));
    TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, 8);
    TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_UINT);
    TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, channels);
    TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, channels <= 2 ? PHOTOMETRIC_MINISBLACK : PHOTOMETRIC_RGB);
    if (channels == 2 || channels == 4) {
        std::uint16_t extra = EXTRASAMPLE_UNASSALPHA;
        TIFFSetField(tif, TIFFTAG_EXTRASAMPLES, 1, &extra);
    }
    TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
    TIFFSetField(tif, TIFFTAG_PREDICTOR, PREDICTOR_HORIZONTAL);
    TIFFSetField(tif, TIFFTAG_TILEWIDTH, std::uint32_t(kCogTileSize));
    TIFFSetField(tif, TIFFTAG_TILELENGTH, std::uint32_t(kCogTileSize));
    if (georef) write_geotiff_georef(tif, *georef, file.path());
    const std::size_t px = std::size_t(channels), t = std::size_t(kCogTileSize);
    std::vector<std::uint8_t> tile(t * t * px);
    for (int r0 = 0; r0 < image.height; r0 += kCogTileSize)
        for (int c0 = 0; c0 < image.width; c0 += kCogTileSize) {
            // Edge tiles are padded with zeros (transparent, and cheap to compress).
            std::fill(tile.begin(), tile.end(), std::uint8_t(0));
            const int rows = std::min(kCogTileSize, image.height - r0), cols = std::min(kCogTileSize, image.width - c0);
            for (int r = 0; r < rows; ++r)
                std::memcpy(tile.data() + std::size_t(r) * t * px,
                            image.data + (std::size_t(r0 + r) * std::size_t(image.width) + std::size_t(c0)) * px,
                            std::size_t(cols) * px);
            const ttile_t index = TIFFComputeTile(tif, std::uint32_t(c0), std::uint32_t(r0), 0, 0);
            if (TIFFWriteEncodedTile(tif, index, tile.data(), tmsize_t(tile.size())) < 0)
                throw input_error(file.path(), "writing TIFF failed: " + file.last_error());
        }
    if (!TIFFWriteDirectory(tif)) throw input_error(file.path(), "writing TIFF failed: " + file.last_error());
}

// Little-endian reading and writing of the TIFF words (up to 8 bytes).
std::uint64_t get(const std::vector<std::uint8_t>& b, std::size_t at, int bytes, const std::string& path) {
    if (at + std::size_t(bytes) > b.size()) throw input_error(path, "TIFF truncated while laying out the COG");
    std::uint64_t v = 0;
    for (int k = bytes - 1; k >= 0; --k) v = (v << 8) | b[at + std::size_t(k)];
    return v;
}
void put(std::vector<std::uint8_t>& b, std::size_t at, std::uint64_t v, int bytes) {
    for (int k = 0; k < bytes; ++k) b[at + std::size_t(k)] = std::uint8_t(v >> (8 * k));
}

// Where classic TIFF and BigTIFF differ: the width of offsets and value counts, of an IFD's
// entry count, and so of its entries and of what fits inline.
struct TiffWords {
    bool big = false;
    std::size_t header() const { return big ? 16 : 8; }
    int offset() const { return big ? 8 : 4; }        // file offsets and an entry's value count
    int entry_count() const { return big ? 8 : 2; }   // the number of entries opening an IFD
    std::size_t entry() const { return big ? 20 : 12; }
    std::size_t inline_bytes() const { return big ? 8 : 4; }
    std::size_t ifd(std::size_t entries) const {
        return std::size_t(entry_count()) + entry() * entries + std::size_t(offset());
    }
};

std::size_t type_size(std::uint16_t type) {
    switch (type) {
        case 1: case 2: case 6: case 7: return 1;  // BYTE, ASCII, SBYTE, UNDEFINED
        case 3: case 8: return 2;                  // SHORT, SSHORT
        case 4: case 9: case 11: case 13: return 4;  // LONG, SLONG, FLOAT, IFD
        case 5: case 10: case 12: return 8;        // RATIONAL, SRATIONAL, DOUBLE
        case 16: case 17: case 18: return 8;       // LONG8, SLONG8, IFD8 (BigTIFF)
        default: return 0;
    }
}

struct Entry {
    std::uint16_t tag = 0, type = 0;
    std::uint64_t count = 0;
    std::vector<std::uint8_t> value;  // count * type_size bytes
};

// A compressed tile, where it lies in the TIFF being laid out (not copied: the input is the
// one whole-file buffer the layout holds).
struct TileBytes {
    std::size_t at = 0, size = 0;
};

struct Ifd {
    std::vector<Entry> entries;
    std::vector<TileBytes> tiles;  // in TIFF order: plane by plane, each row-major
};

TiffWords read_header(const std::vector<std::uint8_t>& b, const std::string& path) {
    if (b.size() >= 8 && b[0] == 'I' && b[1] == 'I') {
        if (get(b, 2, 2, path) == 42) return TiffWords{false};
        if (get(b, 2, 2, path) == 43 && get(b, 4, 2, path) == 8 && get(b, 6, 2, path) == 0) return TiffWords{true};
    }
    throw input_error(path, "expected a little-endian TIFF or BigTIFF to lay out as a COG");
}

std::vector<Ifd> read_ifds(const std::vector<std::uint8_t>& b, const TiffWords& words, const std::string& path) {
    std::vector<Ifd> ifds;
    const int ow = words.offset();
    std::uint64_t offset = get(b, words.header() - std::size_t(ow), ow, path);
    while (offset != 0) {
        if (ifds.size() > 64) throw input_error(path, "too many TIFF directories");
        Ifd ifd;
        const std::uint64_t n = get(b, offset, words.entry_count(), path);
        if (n > 4096) throw input_error(path, "implausible TIFF directory of " + std::to_string(n) + " entries");
        std::vector<std::uint64_t> tile_offsets, tile_counts;
        for (std::uint64_t i = 0; i < n; ++i) {
            const std::size_t at = offset + std::size_t(words.entry_count()) + words.entry() * std::size_t(i);
            Entry e;
            e.tag = std::uint16_t(get(b, at, 2, path));
            e.type = std::uint16_t(get(b, at + 2, 2, path));
            e.count = get(b, at + 4, ow, path);
            if (type_size(e.type) == 0) throw input_error(path, "unexpected TIFF field type " + std::to_string(e.type));
            if (e.count > b.size()) throw input_error(path, "TIFF truncated while laying out the COG");
            const std::size_t bytes = type_size(e.type) * std::size_t(e.count);
            const std::size_t value_at = at + 4 + std::size_t(ow);
            const std::size_t from = bytes <= words.inline_bytes() ? value_at : get(b, value_at, ow, path);
            if (from + bytes > b.size()) throw input_error(path, "TIFF truncated while laying out the COG");
            e.value.assign(b.begin() + std::ptrdiff_t(from), b.begin() + std::ptrdiff_t(from + bytes));
            if (e.tag == kTagTileOffsets || e.tag == kTagTileByteCounts) {
                auto& out = e.tag == kTagTileOffsets ? tile_offsets : tile_counts;
                const int w = int(type_size(e.type));
                for (std::uint64_t k = 0; k < e.count; ++k)
                    out.push_back(get(e.value, std::size_t(k) * std::size_t(w), w, path));
            }
            ifd.entries.push_back(std::move(e));
        }
        if (tile_offsets.empty() || tile_offsets.size() != tile_counts.size())
            throw input_error(path, "expected a tiled TIFF to lay out as a COG");
        for (std::size_t k = 0; k < tile_offsets.size(); ++k) {
            if (tile_offsets[k] > b.size() || tile_counts[k] > b.size() - tile_offsets[k])
                throw input_error(path, "TIFF truncated while laying out the COG");
            ifd.tiles.push_back({std::size_t(tile_offsets[k]), std::size_t(tile_counts[k])});
        }
        ifds.push_back(std::move(ifd));
        offset = get(b, offset + words.ifd(std::size_t(n)) - std::size_t(ow), ow, path);
    }
    return ifds;
}

std::string ghost_area(std::size_t header) {
    std::string md =
        "LAYOUT=IFDS_BEFORE_DATA\nBLOCK_ORDER=ROW_MAJOR\nBLOCK_LEADER=SIZE_AS_UINT4\n"
        "BLOCK_TRAILER=LAST_4_BYTES_REPEATED\nKNOWN_INCOMPATIBLE_EDITION=NO\n";
    char head[64];
    std::snprintf(head, sizeof head, "GDAL_STRUCTURAL_METADATA_SIZE=%06zu bytes\n", md.size());
    std::string ghost = head + md;
    if ((header + ghost.size()) % 2) {  // the first IFD starts on a word boundary
        md += ' ';
        std::snprintf(head, sizeof head, "GDAL_STRUCTURAL_METADATA_SIZE=%06zu bytes\n", md.size());
        ghost = head + md;
    }
    return ghost;
}

// The COG as the bytes before the first tile (header, ghost, IFDs and their values) and the
// tiles in file order, each to be written behind its size and before its last 4 bytes.
struct CogPlan {
    std::vector<std::uint8_t> head;
    std::vector<TileBytes> tiles;
    std::size_t size = 0;  // of the whole file
};

CogPlan plan_cog(const std::vector<std::uint8_t>& tiff, const std::string& path) {
    const TiffWords words = read_header(tiff, path);
    std::vector<Ifd> ifds = read_ifds(tiff, words, path);
    const std::string ghost = ghost_area(words.header());
    const int ow = words.offset();

    // Where each IFD and its out-of-line values go, then where the tiles start. The tile
    // offsets are LONG (LONG8 in a BigTIFF), their sizes LONG: a tile is far below 4 GiB.
    std::size_t at = words.header() + ghost.size();
    std::vector<std::size_t> ifd_at(ifds.size());
    for (std::size_t i = 0; i < ifds.size(); ++i) {
        ifd_at[i] = at;
        at += words.ifd(ifds[i].entries.size());
        for (Entry& e : ifds[i].entries) {
            if (e.tag == kTagTileOffsets || e.tag == kTagTileByteCounts) {
                e.type = e.tag == kTagTileOffsets && words.big ? 16 : 4;  // LONG8 or LONG
                e.value.assign(std::size_t(e.count) * type_size(e.type), 0);
            }
            if (e.value.size() > words.inline_bytes()) at += e.value.size() + (e.value.size() % 2);
        }
    }
    CogPlan plan;
    plan.head.assign(at, 0);
    // Tiles: the smallest overview first, the full resolution last; leader + data + trailer.
    std::vector<std::vector<std::uint64_t>> tile_at(ifds.size());
    for (std::size_t i = ifds.size(); i-- > 0;)
        for (const TileBytes& tile : ifds[i].tiles) {
            tile_at[i].push_back(at + 4);
            plan.tiles.push_back(tile);
            at += 4 + tile.size + (tile.size >= 4 ? 4 : 0);
        }
    if (!words.big && at > 0xFFFFFFFFull) throw input_error(path, "too large for a classic-TIFF COG (over 4 GiB)");
    plan.size = at;

    std::vector<std::uint8_t>& out = plan.head;
    out[0] = 'I', out[1] = 'I';
    if (words.big) {
        put(out, 2, 43, 2), put(out, 4, 8, 2), put(out, 6, 0, 2);
    } else {
        put(out, 2, 42, 2);
    }
    put(out, words.header() - std::size_t(ow), ifd_at.empty() ? 0 : ifd_at[0], ow);
    std::memcpy(out.data() + words.header(), ghost.data(), ghost.size());
    for (std::size_t i = 0; i < ifds.size(); ++i) {
        const std::size_t p = ifd_at[i];
        const std::size_t n = ifds[i].entries.size();
        std::size_t values = p + words.ifd(n);
        put(out, p, n, words.entry_count());
        for (std::size_t k = 0; k < n; ++k) {
            Entry& e = ifds[i].entries[k];
            const int w = int(type_size(e.type));
            if (e.tag == kTagTileOffsets)
                for (std::size_t t = 0; t < tile_at[i].size(); ++t) put(e.value, std::size_t(w) * t, tile_at[i][t], w);
            if (e.tag == kTagTileByteCounts)
                for (std::size_t t = 0; t < ifds[i].tiles.size(); ++t)
                    put(e.value, std::size_t(w) * t, ifds[i].tiles[t].size, w);
            const std::size_t q = p + std::size_t(words.entry_count()) + words.entry() * k;
            put(out, q, e.tag, 2);
            put(out, q + 2, e.type, 2);
            put(out, q + 4, e.count, ow);
            const std::size_t value_at = q + 4 + std::size_t(ow);
            if (e.value.size() <= words.inline_bytes()) {
                std::memcpy(out.data() + value_at, e.value.data(), e.value.size());
            } else {
                put(out, value_at, values, ow);
                std::memcpy(out.data() + values, e.value.data(), e.value.size());
                values += e.value.size() + (e.value.size() % 2);
            }
        }
        put(out, p + words.ifd(n) - std::size_t(ow), i + 1 < ifds.size() ? ifd_at[i + 1] : 0, ow);
    }
    return plan;
}

// A tile's 4-byte size leader, or its trailer (its last 4 bytes again; none under 4 bytes).
std::array<std::uint8_t, 4> size_leader(const TileBytes& tile) {
    std::array<std::uint8_t, 4> b{};
    for (int k = 0; k < 4; ++k) b[std::size_t(k)] = std::uint8_t(std::uint32_t(tile.size) >> (8 * k));
    return b;
}
std::size_t trailer_size(const TileBytes& tile) { return tile.size >= 4 ? 4 : 0; }

}  // namespace

std::vector<std::pair<int, int>> cog_overview_sizes(int width, int height) {
    std::vector<std::pair<int, int>> sizes;
    while (width > kCogTileSize || height > kCogTileSize) {
        width = (width + 1) / 2, height = (height + 1) / 2;
        sizes.emplace_back(width, height);
    }
    return sizes;
}

void lay_out_as_cog(const std::filesystem::path& file, const std::string& path) {
    std::vector<std::uint8_t> tiff;
    {
        std::ifstream in(file, std::ios::binary);
        if (!in) throw input_error(path, "cannot read back the TIFF to lay out as a COG");
        tiff.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    // Written straight from the TIFF's bytes: the layout holds the file once, not a laid-out
    // copy too (a thousand-band insolation output can be as large as its map).
    const CogPlan plan = plan_cog(tiff, path);
    std::FILE* f = std::fopen(file.c_str(), "wb");
    if (!f) throw input_error(path, "cannot write");
    bool ok = std::fwrite(plan.head.data(), 1, plan.head.size(), f) == plan.head.size();
    for (const TileBytes& tile : plan.tiles) {
        if (!ok) break;
        const auto size = size_leader(tile);
        const std::uint8_t* data = tiff.data() + tile.at;
        ok = std::fwrite(size.data(), 1, 4, f) == 4 && std::fwrite(data, 1, tile.size, f) == tile.size &&
             std::fwrite(data + tile.size - trailer_size(tile), 1, trailer_size(tile), f) == trailer_size(tile);
    }
    if (std::fclose(f) != 0 || !ok) throw input_error(path, "cannot write (disk full?)");
}

void write_cog_u8(const std::filesystem::path& path, int width, int height, int channels, const std::uint8_t* data,
                  const geo::Georef& georef) {
    if (width <= 0 || height <= 0) throw input_error(path.string(), "cannot write an empty image");
    if (channels < 1 || channels > 4)
        throw input_error(path.string(), "an 8-bit image has 1 to 4 channels, not " + std::to_string(channels));
    if (!georef.valid()) throw input_error(path.string(), "a Cloud-Optimized GeoTIFF needs georeferencing");
    write_atomically(path, [&](const std::filesystem::path& tmp) {
        {
            TiffFile file(tmp, "wl");
            Image level;
            level.width = width, level.height = height, level.data = data;
            write_directory(file, level, channels, &georef);
            while (level.width > kCogTileSize || level.height > kCogTileSize) {
                level = halved(level, channels);
                write_directory(file, level, channels, nullptr);
            }
            file.close();
        }
        lay_out_as_cog(tmp, path.string());
    });
}

}  // namespace ts::raster
