#pragma once
// Where each pixel of a tile falls on the DEM. A tile is a window of the global pixel grid of its
// pixel zoom (web_mercator.hpp); every pixel centre is computed from its global index alone, then
// carried to the DEM's level-0 pixel (edge) coordinates: through lon/lat and the DEM's CRS, or,
// for a north-up WGS84 DEM, per column and per row (Mercator and the DEM grid are then both
// separable in lon and lat: the same numbers, 2n transforms instead of n^2).
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "core/dem/dem.hpp"
#include "core/tiles/web_mercator.hpp"

namespace ts::tiles {

// A tile as a window of the global pixel grid.
struct TileFrame {
    TileId tile;
    int size = 256;         // pixels per side
    int pixel_zoom = 0;     // z + log2(size / 256)
    std::int64_t col0 = 0;  // global index of its first column / row
    std::int64_t row0 = 0;
};
// Throws std::invalid_argument for a size that is not 256 * 2^k.
TileFrame tile_frame(const TileId& t, int tile_size);

class TilePixelMap {
public:
    explicit TilePixelMap(const dem::Dem& dem);

    // Level-0 edge coordinates of the centres of pixels [-halo, size + halo)^2, row-major
    // ((size + 2 halo)^2 entries); NaN where the pixel does not map (off the CRS's domain).
    void locate(const TileFrame& f, int halo, std::vector<glm::dvec2>& at) const;
    // True where a located pixel shows data: inside the DEM and not over a source void.
    bool covered(glm::dvec2 p) const;
    // Pixel positions depend on the column alone (x) and the row alone (y): locate() then fills
    // every row with the same x and every column with the same y.
    bool separable() const { return separable_; }
    bool has_voids() const { return has_voids_; }

private:
    const dem::Dem& dem_;
    bool separable_ = false;
    bool has_voids_ = false;
};

}  // namespace ts::tiles
