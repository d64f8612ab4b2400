#pragma once
// A digital elevation model in memory: heights on a georeferenced grid, with its voids.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/geo/georef.hpp"

namespace ts::dem {

struct Dem {
    int width = 0;
    int height = 0;
    // Row-major, row 0 is the first row of the file (north-up for every supported input).
    // NaN marks a void until fill_voids() replaces it; void_mask keeps the record either way.
    std::vector<float> z;
    // 1 where the source had no data (nodata value, SRTM -32768), 0 elsewhere.
    std::vector<std::uint8_t> void_mask;
    geo::Georef georef;
    // Vertical datum of the heights, e.g. "EGM96 geoid" for SRTM; "unknown" if the file is silent.
    std::string vertical_datum = "unknown";
    // The unit the file stored the heights in ("metre", "US survey foot"): z is in metres always.
    std::string height_unit = "metre";
    // Who made the heights, as the files say (a GeoTIFF's copyright tag, a Copernicus DEM's
    // DTED metadata, SRTM for .hgt); empty when they are silent. Maps credit it.
    std::string credit;
    // The file(s) this came from, for messages.
    std::string source;

    std::size_t index(int col, int row) const { return std::size_t(row) * std::size_t(width) + std::size_t(col); }
    float at(int col, int row) const { return z[index(col, row)]; }
    bool is_void(int col, int row) const { return void_mask[index(col, row)] != 0; }
    std::size_t void_count() const;
};

}  // namespace ts::dem
