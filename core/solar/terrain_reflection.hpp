#pragma once
// The reflected irradiation from the terrain a texel actually sees (docs/insolation.md,
// "Reflected"): a second pass over an insolation map, a horizon-based gather on the DEM as
// screen-space ambient occlusion does it (GTAO, SSDO).
//
// Every texel's global irradiation from the first pass, G_p per period, is the light leaving
// the terrain there: a Lambertian point reflects radiance albedo G_p / pi. G_p includes the
// first pass's isotropic reflected estimate, which stands for the higher bounces.
//
// Per receiver, along `directions` azimuths (a subset of the horizons' D, so the horizon
// angles there are exact) the gather marches outwards at geometrically growing distances,
// keeping the highest elevation seen so far (starting at the receiver's own tangent plane:
// below it is behind the receiver). A sample above that maximum covers the elevation interval
// between them with its G. What the exact horizon holds above the march's maximum (terrain
// beyond the radius or between samples) is lit like the first pass's isotropic ground. The
// weight of an interval [h0, h1] in a sector dphi is dphi (F(h0) - F(h1)), F the integral of
// (n.w) cos(e) de from h to pi/2 (as in the tilted sky view factor): the cosine-weighted solid
// angle of that piece of terrain.
//
// The weights are then scaled so that they sum to pi (1 - svf), the exact blocked part of the
// hemisphere of the first pass (its D azimuths): the gather decides where the terrain is lit,
// the first pass how much terrain there is. Hence an open flat texel gets 0, and a texel whose
// seen terrain is lit like open flat ground gets the first pass's value exactly.
#include <span>
#include <vector>

#include "core/solar/insolation_map.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/visibility/horizon_set.hpp"
#include "core/visibility/terrain_gather.hpp"

namespace ts::solar {

// Defaults from the error against a fine gather (64 directions, radius 250, growth 1.1) and
// the cost on a whole SRTM tile (docs/insolation.md, "Reflected"): 16 directions, 64 texels, 1.2.
using TerrainReflectionSettings = visibility::TerrainGatherSettings;

// Throws ts::InputError on directions outside [0, 1024], a radius outside [1, 1024] texels or a
// growth outside [1.01, 4].
void check_reflection_settings(const TerrainReflectionSettings& s);

// What the gather reads. Arrays [texel * periods + period] over the grid, NaN on void texels.
struct ReflectionInputs {
    const terrain::HeightGrid* grid = nullptr;
    const visibility::HorizonSet* horizons = nullptr;  // over the whole grid
    const render::NormalField* normals = nullptr;
    int periods = 0;
    std::span<const float> global;               // the first pass's global irradiation
    std::span<const float> isotropic_reflected;  // the first pass's reflected (isotropic ground)
    std::span<const float> svf;                  // per texel: the tilted sky view factor
    double albedo = 0.2;
    // Earth curvature as the horizons have it: 1 / (2 R_eff) or 0 (earth_curvature.hpp).
    double curvature = 0;
};

// The reflected irradiation per texel and period ([texel * periods + period]), NaN where the
// receiver is void. Rows in parallel on `threads` (0: every core).
std::vector<float> gather_terrain_reflection(const ReflectionInputs& in, const TerrainReflectionSettings& s,
                                             int threads);

// One receiver's gather before the scaling, for tests and diagnostics: the sum of G_p times
// the weight over the seen terrain, the seen terrain's weight and the weight left to the
// isotropic ground (beyond the radius, or samples without a G). seen_weight + far_weight
// approximates pi (1 - svf).
struct TexelGather {
    std::vector<double> seen;  // per period
    double seen_weight = 0, far_weight = 0;
};
TexelGather gather_texel(const ReflectionInputs& in, const TerrainReflectionSettings& s, int col, int row);

// Pass 2 on a map from integrate_insolation over the same grid, horizons and normals: its
// reflected bands from the gather, its global bands re-summed (beam + diffuse + reflected).
// `albedo` is the one the first pass used. texel_albedo (empty: `albedo` everywhere) gives each
// texel its own: the seen terrain reflects with its albedo, and the isotropic ground (the
// gather off, or beyond its reach) has the receiver's (its surroundings are most like it).
// Nothing changes when the gather is off and there is no texel_albedo.
void apply_terrain_reflection(InsolationMap& map, const terrain::HeightGrid& grid,
                              const visibility::HorizonSet& horizons, const render::NormalField& normals,
                              double albedo, const TerrainReflectionSettings& s, int threads,
                              std::span<const float> texel_albedo = {});

}  // namespace ts::solar
