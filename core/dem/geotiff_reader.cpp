// GeoTIFF DEMs read whole into a Dem: the header and its checks (geotiff_header.hpp), then
// every block decoded into place (tiff_samples.hpp). Before the raster is allocated, its
// blocks are checked against the file's size and the memory available.
#include <vector>

#include "core/dem/decode_limits.hpp"
#include "core/dem/geotiff_header.hpp"
#include "core/dem/read_dem.hpp"

namespace ts::dem {

Dem read_geotiff(const std::filesystem::path& path) {
    raster::TiffFile file(path, "r");
    const GeoTiffHeader header = read_geotiff_header(file, kMaxDemCells);
    require_memory_for(header.layout.source, "decoding", std::uint64_t(header.layout.width),
                       std::uint64_t(header.layout.height), header.block_bytes);

    Dem dem = allocate_dem(header.layout);
    const SampleDecoder decoder(header.type, header.nodata, header.metres_per_unit);
    const std::size_t row_bytes = std::size_t(header.blocks.block_w) * std::size_t(decoder.sample_size());
    std::vector<std::uint8_t> block(header.block_bytes);
    for (std::uint32_t i = 0; i < header.blocks.count(); ++i) {
        const GeoTiffHeader::Cells c = header.cells(i);
        const bool stored = read_geotiff_block(file, header, i, block.data());
        for (int r = 0; r < c.rows; ++r) {
            const std::size_t at = dem.index(c.col0, c.row0 + r);
            if (stored)
                decoder.decode(block.data() + std::size_t(r) * row_bytes, std::size_t(c.cols), &dem.z[at], &dem.void_mask[at]);
            else
                decoder.decode_sparse(std::size_t(c.cols), &dem.z[at], &dem.void_mask[at]);
        }
    }
    return dem;
}

}  // namespace ts::dem
