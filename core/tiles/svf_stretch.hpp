#pragma once
// The svf style's grey stretch, shared by the style and the legend drawn for its tile sets.
// svf of open ground is 1; in relief valleys and gorges it falls towards ~0.5. The stretch
// spends the grey range on that interval: kSvfBlack..1 -> black..white (display-linear, then
// sRGB-encoded at the pixel).
namespace ts::tiles {

constexpr float kSvfBlack = 0.55f;

}  // namespace ts::tiles
