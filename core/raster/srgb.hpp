#pragma once
// The sRGB transfer functions (IEC 61966-2-1) of 8-bit images: how the bytes of an sRGB PNG or
// TIFF encode linear light. The renderer encodes with the OETF (core/render/tone_map.hpp), the
// orthophoto reader decodes with the EOTF (core/material/material_sources.hpp).
namespace ts::raster {

// Linear [0, 1] -> encoded [0, 1] (input clamped).
float srgb_oetf(float linear);
// Its inverse: encoded [0, 1] -> linear [0, 1] (input clamped).
float srgb_eotf(float encoded);

}  // namespace ts::raster
