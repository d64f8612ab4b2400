#pragma once
// What a style with visibility shades one block of a DEM level from (shade_source.hpp): the
// level's grids, the block's core and the window it is shaded on, the far field beyond, the
// shading, and the shared steps the styles call (one frame of radiance on the window, the
// window's svf). Each style's shade_block (relief_style.cpp, svf_style.cpp, color_style.cpp)
// turns them into its values.
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "core/material/material.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/tiles/tile_style.hpp"
#include "core/visibility/far_field_horizons.hpp"
#include "core/visibility/visibility_backend.hpp"

namespace ts {
class ProgressBar;
}
namespace ts::render {
class ShadingState;
}

namespace ts::tiles {

// A rectangle of the level: a block's core or window.
using Rect = visibility::ReceiverWindow;

struct BlockShading {
    const terrain::HeightGrid& grid;       // the level, heights as shaded (exaggerated)
    const terrain::HeightGrid& true_grid;  // its true heights (empty unless the style needs them)
    Rect window, core;                     // shaded on the window, kept on the core
    bool whole = false;                    // the block is the whole level (window == grid)
    const visibility::FarField* far = nullptr;  // the terrain beyond the window, or none
    const TileShading& shading;            // with this block's directions
    double flat = 1.0;                     // luminance of open flat ground (relative_to_flat)
    ProgressBar* progress = nullptr;
    // The level's texel latitudes (degrees, level-sized) for a style that needs them, else null.
    const std::vector<float>* latitude = nullptr;
};

// One grey Lambert material everywhere: relief shows form, not land cover.
render::MaterialRaster grey_materials(std::size_t n, float albedo);
// The grey relief's albedo (`--colors grey`'s, 0.18): what its bounced light reflects.
inline constexpr float kReliefAlbedo = 0.18f;

// The materials of the window from its grid (heights as shaded) and its true heights.
using BlockMaterials =
    std::function<render::MaterialRaster(const terrain::HeightGrid& window, const terrain::HeightGrid& true_window)>;

// Sees the shading state of a block's window (its diffuse transfer kept) instead of a frame.
using StateInspector = std::function<void(const render::ShadingState&)>;

// One frame of radiance per window texel under the shading's sun and sky; the true heights are
// windowed for `materials` when `true_heights`. With `inspect`: the window's shading state goes
// there and nothing is returned (lightable_style.cpp keeps its transfer and normals).
std::vector<glm::vec3> render_block(const BlockShading& block, const BlockMaterials& materials, bool true_heights,
                                    const StateInspector* inspect = nullptr);

// `request` (its horizon window set to the block's) for the block's window: through the far
// field beyond the halo when there is one (`window_texels`: the window as a grid of its own, window_grid()),
// else swept over the whole level. The window's products, the halo's void with a far field.
visibility::VisibilityResult block_visibility(const BlockShading& block, visibility::VisibilityRequest request,
                                              const terrain::HeightGrid& window_texels);

// The sky view factor per window texel (NaN where undefined).
std::vector<float> block_svf(const BlockShading& block);

// Luminance of an open flat texel of albedo 1 under the same light, at the grid's spacing: the
// reference that makes relief and color independent of the sky's absolute units.
double flat_reference(const terrain::HeightGrid& like, const TileShading& s);

// The diffuse transfer T_d of that open flat texel (what a lightable tile's reader divides by).
std::array<float, 16> flat_diffuse_transfer(const TileShading& s);

// A window of a grid as a grid of its own, its heights (and void mask) copied into `z`/`voids`.
terrain::HeightGrid window_grid(const terrain::HeightGrid& g, const Rect& w, std::vector<float>& z,
                                std::vector<std::uint8_t>& voids);

}  // namespace ts::tiles
