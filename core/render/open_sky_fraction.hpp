#pragma once
// The share of the cosine-weighted sky each texel's terrain lets it see: <T_d, L> for a sky of
// radiance 1 over the upper hemisphere and no sun, i.e. (1/pi) integral of V(w) max(0, n.w) dw
// through the same transfer the frames use (so its low bias on open ground, docs/rendering.md,
// cancels in ratios with the frame's sky term). What a blocker standing in a receiver's open sky
// takes a share of: an aircraft covering a fraction c of the hemisphere above a valley floor
// that sees V of it takes c / V of the floor's sky light, not c (ts_open_sky_share,
// core/blockers/sphere_occlusion_shared.h). The bounced light the transfer also carries
// (bounce_transfer.hpp) is taken out: it is not sky.
#include <vector>

#include "core/render/frame_renderer.hpp"

namespace ts::render {

// One value per texel, in [0, 1]; water texels and texels without albedo get 1. Renders one
// frame through `frame` (its sun visibility then is that of a sun below the horizon).
std::vector<float> open_sky_fraction(FrameRenderer& frame);

}  // namespace ts::render
