#pragma once
// A Cloud-Optimized GeoTIFF of a float32 raster of any number of bands: band-separate planes
// (PLANARCONFIG_SEPARATE, GDAL's INTERLEAVE=BAND, so that reading one band of thousands reads
// that band's tiles only), 256-px deflate tiles with the floating-point predictor, NaN as
// nodata (GDAL_NODATA "nan"), band descriptions and units (GDAL_METADATA), internal overviews
// halved until the smallest fits in one tile, and the layout of cog_writer.hpp (lay_out_as_cog:
// each IFD's tiles band by band, the smallest overview first).
#include <filesystem>
#include <string>
#include <vector>

#include "core/geo/georef.hpp"

namespace ts::raster {

// `bands` band-sequential planes of width*height, row-major, georeferenced like `georef`;
// descriptions[b] and units[b] (either list may be empty or shorter) become band b+1's GDAL
// description and unit type; image_description, if any, the TIFF's ImageDescription (what a
// shard of a job records about itself, read back by read_float_tiff). Overviews average each 2x2 block over its finite values only (a
// block with none is NaN). Written atomically; a BigTIFF when the uncompressed tiles pass 3 GiB.
void write_float_cog(const std::filesystem::path& path, int width, int height, int bands, const float* data,
                     const geo::Georef& georef, const std::vector<std::string>& descriptions = {},
                     const std::vector<std::string>& units = {}, const std::string& image_description = "");

}  // namespace ts::raster
