#pragma once
// How much a zoom exaggerates the relief, and which DEM level it is shaded from.
//
// A fixed z-factor makes low zooms look flat: slopes averaged over kilometre-wide pixels are
// gentle, and Mercator's scale 1/cos(lat) stretches the map's metres besides (that one is
// corrected exactly, per pixel row, where gradients are taken in map metres: tile_horn.hpp).
// The exaggeration is a function of the *pixel zoom* P (web_mercator.hpp: a 512-px tile at zoom
// z is shaded as the 256-px tiles of zoom z+1, which show the same pixels):
//
//   E(P) = 2^(max(0, 12 - P) / 3)      1 at z12 and above (~38 m map pixels), 2 at z9, 4 at z6,
//                                      16 at z0
//
// multiplied by --z-factor; --exaggeration E replaces E(P) (1 = true heights at every zoom).
namespace ts::tiles {

inline constexpr int kExaggerationFreeZoom = 12;

double zoom_exaggeration(int pixel_zoom);

// The DEM pyramid level (0 = the DEM, L = 2^L texels averaged per side) whose texels are the
// largest not coarser than a pixel of `pixel_ground_m` metres: so no zoom shades from a grid
// finer than it can show (aliasing) or coarser (blur). `max_level` bounds it.
int pyramid_level_for(double dem_texel_m, double pixel_ground_m, int max_level);

}  // namespace ts::tiles
