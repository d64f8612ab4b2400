#pragma once
// A GeoTIFF DEM's header: size, sample type, nodata, compression, blocks (strips or tiles,
// any compression libtiff knows) and georeferencing (core/raster/geotiff_georef), checked
// before any cell is decoded; and the decoding of one block. Shared by the whole-file reader
// (read_geotiff) and the window reader (DemSource), which decodes only the blocks it needs.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "core/dem/dem_layout.hpp"
#include "core/dem/tiff_samples.hpp"
#include "core/raster/tiff_file.hpp"

namespace ts::dem {

// The raster's blocks: tiles, or strips of `block_h` whole rows. Block i is at column
// i % across, row i / across of the block grid, as libtiff numbers tiles and strips.
struct TiffBlocks {
    bool tiled = false;
    std::uint32_t block_w = 0, block_h = 0;
    std::uint32_t across = 0, down = 0;
    std::uint64_t count() const { return std::uint64_t(across) * down; }
    const char* noun() const { return tiled ? "tile" : "strip"; }
};

struct GeoTiffHeader {
    DemLayout layout;  // georef, vertical datum (GeoKeys, else GDAL's DTED metadata), source
    SampleType type = SampleType::u8;
    std::optional<double> nodata;  // GDAL_NODATA (in the file's unit)
    double metres_per_unit = 1.0;  // the heights' unit (layout.height_unit): samples are scaled by it
    std::uint16_t compression = 1;
    TiffBlocks blocks;
    // The largest decoded block: a whole tile, or the first (tallest) strip.
    std::uint64_t block_bytes = 0;

    // Where block i's cells are: its first cell and how many of its cells lie inside the image.
    struct Cells {
        int col0 = 0, row0 = 0, cols = 0, rows = 0;
    };
    Cells cells(std::uint32_t i) const;
    // The bytes libtiff decodes block i into: a whole tile (edge tiles are padded), or the
    // rows of the strip that lie inside the image. Rows are block_w samples apart either way.
    std::uint64_t decoded_bytes(std::uint64_t i) const;
};

// Reads and checks the header of an open file: one band of a supported sample type, a codec
// this libtiff has, block lists that match the image and whose blocks fit in the file and
// could decode to what they claim (so a few hundred bytes cannot pass for gigabytes), and
// georeferencing. `max_cells` caps width x height for readers that allocate the whole grid;
// each side must fit an int in any case. Throws ts::InputError "path: problem".
GeoTiffHeader read_geotiff_header(const raster::TiffFile& file, std::uint64_t max_cells);

// Decodes block i into `out` (decoded_bytes(i) bytes); false, with `out` untouched, for a
// sparse block (no bytes, SampleDecoder::decode_sparse). Throws ts::InputError for a block
// libtiff cannot decode whole.
bool read_geotiff_block(const raster::TiffFile& file, const GeoTiffHeader& header, std::uint32_t i, std::uint8_t* out);

}  // namespace ts::dem
