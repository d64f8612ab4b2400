#pragma once
// One level-0 tile of a streamed DEM (core/fly/terrain_overview.hpp): what the CDLOD levels below
// the overview's draw inside it. A tile spans `tile_texels` level-0 texels a side and holds
// tile_texels + 1 samples (the last row and column are the next tile's first, so neighbouring
// tiles give a shared edge the same heights). Voids take the overview's (bilinear between its
// filled points): a texel's fill then does not depend on which window it was read in, and on the
// points it is the points' own value, where the coarser levels meet it.
//
// Shading: the tile's window (the tile grown by `halo` texels a side, clipped to the grid) as a
// DEM of its own, render::Scene on it as `render` shades a whole DEM, its horizons exact inside
// the window and raised by the far field beyond it (visibility::WindowFarFieldVisibility), and
// its sun shadows from the far field too. The Scene (the view-independent state: visibility,
// transfer) is kept while the tile is resident; a new sun only runs its frame again.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/render/bounce_transfer.hpp"
#include "core/render/horizon_sky_light.hpp"
#include "core/dem/dem.hpp"
#include "core/dem/dem_source.hpp"
#include "core/fly/terrain_overview.hpp"
#include "core/render/frame_renderer.hpp"
#include "core/render/render_scene.hpp"
#include "core/render/texel_sun_split.hpp"

namespace ts::visibility {
class FarField;
class WindowFarFieldVisibility;
}

namespace ts::fly {

struct DetailTileLayout {
    int tile_texels = 256;
    int tiles_x = 0, tiles_y = 0;
    int width = 0, height = 0;  // the grid's level-0 texels
    int levels_below = 0;       // the CDLOD levels a tile answers (those below the overview's)
    int patch_quads = 16;
};

// Tiles of 256 texels, or of one node of the finest overview level below when that is larger.
DetailTileLayout detail_tile_layout(const TerrainOverview& overview, int patch_quads);

struct DetailTileKey {
    int tx = 0, ty = 0;
    bool operator==(const DetailTileKey&) const = default;
    auto operator<=>(const DetailTileKey&) const = default;
};

// The tile holding node (level, ix, iy) of a level below the overview's.
DetailTileKey tile_of_node(const DetailTileLayout& layout, int level, int ix, int iy);

struct DetailShadingOptions {
    int halo = 64;           // level-0 texels read around a tile for its shading
    int directions = 16;     // horizon azimuths
    render::BounceSettings bounce;  // light bounced off the terrain
    render::SkyLightSettings sky_light;  // the sky's light over the horizons or through SH
    std::string sky = "clear";
    // Keep each frame's horizon in the sun's azimuth for the fragments (FlySettings::pixel_sun_shadows).
    bool sun_horizon = true;
    render::ColorDesign colors;  // percent stops fitted to the overview's heights, so tiles agree
    int threads = 0;
};

class DetailTile {
public:
    // Reads the tile's window from `source` and shades it (the heavy part: its visibility).
    DetailTile(DetailTileKey key, const DetailTileLayout& layout, const dem::DemSource& source,
               const TerrainOverview& overview, const visibility::FarField& far, const DetailShadingOptions& options);
    ~DetailTile();

    DetailTileKey key() const { return key_; }
    int col0() const { return col0_; }
    int row0() const { return row0_; }
    int samples_x() const { return samples_x_; }
    int samples_y() const { return samples_y_; }
    // samples_x x samples_y heights from (col0, row0), every level-0 texel, voids filled.
    const std::vector<float>& heights() const { return heights_; }
    // The window it was shaded on (voids filled) and its first texel's level-0 position: the
    // near terrain of a point above the tile (the aircraft's horizons).
    const dem::Dem& window() const { return *window_; }
    int window_col0() const { return window_col0_; }
    int window_row0() const { return window_row0_; }
    // The height range of node (level, ix, iy) (grid node indices) of a level below the overview's.
    glm::vec2 node_z(int level, int ix, int iy) const;

    // This sun's light at the tile's samples (render::Scene::render on the window, cut to the
    // tile), packed for the shaders (radiance_pack.hpp): 2 words a sample of the radiance less
    // the sun's diffuse term, 4 of that term's parts (render::split_texel_sun) and the open-sky
    // fraction.
    void light(const render::SunState& sun, std::vector<std::uint32_t>& radiance, std::vector<std::uint32_t>& sun_light);

private:
    DetailTileKey key_;
    DetailTileLayout layout_;
    int col0_ = 0, row0_ = 0, samples_x_ = 0, samples_y_ = 0;
    int window_col0_ = 0, window_row0_ = 0;
    std::vector<float> heights_;
    std::vector<std::vector<glm::vec2>> node_z_;  // per level, tile-local nodes row-major
    std::vector<int> nodes_x_;
    std::unique_ptr<dem::Dem> window_;
    std::unique_ptr<visibility::WindowFarFieldVisibility> backend_;  // the state may keep it
    std::unique_ptr<render::Scene> scene_;
    std::vector<float> open_sky_;  // per window texel
    render::LinearImage image_;
};

// What one resident tile of `tile_texels` shaded with `halo` holds: its window's shading state
// on the CPU (~200 bytes a window texel, docs/tiles.md, and the window's heights, fill flags and
// frame) and its samples on the device (height, radiance, sun part) with their upload copies.
std::size_t detail_tile_bytes(int tile_texels, int halo);

// The overview's filled height at a level-0 position (bilinear between its points).
float overview_height(const TerrainOverview& overview, double col, double row);

}  // namespace ts::fly
