#pragma once
// Legible relief at low zooms: how far `--exaggeration auto` raises a zoom's exaggeration.
//
// E(P) (zoom_exaggeration.hpp) makes up for the slopes' average decline as a DEM is averaged
// over larger pixels. Coarse global grids decline faster: on ETOPO1 at 1 degree, the land's
// 90th-percentile slope is 0.42 degrees (steep_slope), 6.7 at E = 16, and a world map at zoom 2
// was a pale grey with a standard deviation of 6 sRGB codes. So a zoom's exaggeration is raised, where
// needed, until the 90th percentile of the slopes of the DEM level it is shaded from reaches
// kLegibleSlopeDeg, and at most to min(4 E, E^2): never at zoom 12 and above (E = 1), where
// heights are true, and never more than 4 times the rule. Mountain DEMs already pass the
// target at their zooms (Anatolia 90 m: 38 degrees at its native zoom; Grenoble: 41), so they
// keep E(P); ETOPO1 takes 63.5 at zooms 0-4 (22 codes of standard deviation at zoom 2). A DEM
// without slopes keeps E(P).
//
// On a DEM that holds the sea floor (render::kSeaFloorBelowM) only land counts: it is what a
// world map's reader looks for, and the sea floor's trenches and margins are steeper than it.
#include "core/dem/dem.hpp"

namespace ts::tiles {

inline constexpr double kLegibleSlopeDeg = 25.0;
inline constexpr double kLegibleSlopePercentile = 0.9;

// The kLegibleSlopePercentile of the tangents of the slopes of DEM level `level` (2^level texels
// averaged a side) at true heights, over up to 128 x 128 texels spread evenly across it;
// east-west over as many texels as make a square where texels are narrow (isotropic_rows.hpp).
// 0 without enough texels.
double steep_slope(const dem::Dem& dem, int level);

// The exaggeration for a zoom whose rule gives `zoom_e` and whose level's steep slope is
// `steep_tan` (above): zoom_e raised towards tan(kLegibleSlopeDeg) / steep_tan, bounded.
double legible_exaggeration(double zoom_e, double steep_tan);

}  // namespace ts::tiles
