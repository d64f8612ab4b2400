#pragma once
// The ray-traced reference of the `relief` style (render::ReferenceShader, docs/accuracy.md:
// horizons raymarched at 720 azimuths to the grid's edge, the sky integrated over the
// hemisphere with Sky::radiance itself, the sun's disc fraction above the raymarched horizon)
// for a window of one DEM level, normalised as relief is (an open flat texel under the same
// reference light -> kReliefFlatGrey): what `bench tiles --reference` compares the renderer's
// relief with (docs/tiles.md).
#include <vector>

#include "core/dem/dem.hpp"
#include "core/render/reference_shading.hpp"
#include "core/tiles/tile_style.hpp"

namespace ts::tiles {

struct LevelWindow {
    int col0 = 0, row0 = 0, width = 0, height = 0;  // texels of the level
};

// Display-linear relief values 0..1 of the window's texels (row-major; NaN over voids), on DEM
// level `level` with heights times `vertical_scale`, lit as `shading`.
std::vector<float> reference_relief(const dem::Dem& dem, const TileShading& shading, int level, double vertical_scale,
                                    const LevelWindow& window, const render::ReferenceOptions& options = {});

}  // namespace ts::tiles
