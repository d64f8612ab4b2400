#pragma once
// A Cloud-Optimized GeoTIFF of an 8-bit image: 256-px deflate tiles, internal overviews halved
// until the smallest fits in one tile, and GDAL's COG layout (the structural-metadata "ghost"
// after the header, every IFD before any pixel, the smallest overview's tiles first and the full
// resolution last, each tile behind a 4-byte size leader and followed by its last 4 bytes), so
// `gdalinfo` reports LAYOUT=COG and GDAL's validate_cloud_optimized_geotiff.py passes.
//
// libtiff encodes the tiles and the tags (the GeoKeys through write_geotiff_georef, as the other
// writers); the file is then laid out again in COG order by lay_out_as_cog(). Float rasters of any
// band count: float_cog_writer.hpp, on the same layout.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/geo/georef.hpp"

namespace ts::raster {

inline constexpr int kCogTileSize = 256;

// channels 1 (grey), 2 (grey + alpha), 3 (RGB) or 4 (RGBA), interleaved, row-major; written
// atomically. Overviews average each 2x2 block, weighted by alpha when there is one.
void write_cog_u8(const std::filesystem::path& path, int width, int height, int channels, const std::uint8_t* data,
                  const geo::Georef& georef);

// The sizes of the overviews write_cog_u8 adds (halved, rounding up, while either side
// exceeds a tile).
std::vector<std::pair<int, int>> cog_overview_sizes(int width, int height);

// Rewrites `file`, a little-endian TIFF or BigTIFF with tiled IFDs as libtiff writes it (a
// writer's temporary, before its rename), in place in the COG layout above: a byte copy of every
// tag and tile. Each IFD's tiles stay in TIFF order, so a band-separate (PLANARCONFIG_SEPARATE)
// image gets band 1's tiles row-major, then band 2's, ..., the order in which GDAL's GTiff driver
// writes INTERLEAVE=BAND with COPY_SRC_OVERVIEWS (GDAL 3.6's COG driver writes pixel-interleaved
// only). Holds the file in memory once. Throws ts::InputError naming `path` (the user's output)
// for what it cannot read or a classic TIFF whose result passes 4 GiB.
void lay_out_as_cog(const std::filesystem::path& file, const std::string& path);

}  // namespace ts::raster
