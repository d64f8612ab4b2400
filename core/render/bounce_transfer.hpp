#pragma once
// Light that bounces off the terrain, as a transfer of its own (docs/rendering.md, "Bounced
// light"). A texel's sky transfer T_d sees the sky above its horizons (and the sky model's
// ground where its view passes over every blocker); below its horizons it sees terrain, whose
// radiance under the frame's light is, for a Lambertian texel j,
//   B_j = albedo_j <T_j, L>          (L: the sky plus the sun, both in SH)
// which is linear in L. So the light a receiver t gets from the terrain it sees is a transfer
// too, fixed by the terrain and made once:
//   T_b,t = sum_j (w_tj / pi) albedo_j T_j  +  (w_far,t / pi) albedo_t T_flat
// w_tj the cosine-weighted solid angle of the terrain j fills in t's view (the horizon gather,
// core/visibility/terrain_gather.hpp, at its sector azimuths: the exact horizons there), w_far
// the rest of the blocked view in those sectors, what the gather does not reach (beyond its
// radius, off the grid): open flat ground with t's albedo, T_flat the projected clamped cosine
// about the vertical. The weights sum to the blocked view at the sectors' azimuths (scaling them
// to the D horizons' blocked view cost 0.15 s more on 250k texels, for nothing measurable
// against Cycles). A second bounce is the same gather of albedo_j T_b,j.
//
// The sky part then joins the sky transfer (T_d + T_b: no cost per frame). The sun part is
// gathered per frame from the neighbours' own sun and shadows, with the same weights
// (bounce_sun_gather.hpp; SunPart::gather), or <T_b, E_sun Y(s)> over T_b's bands 0..1
// (SunPart::sh: smooth, the neighbours' SH-lit sun, as the browser relights). 0 bounces: no T_b
// (direct light only).
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/render/bounce_sun_gather.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/visibility/horizon_set.hpp"
#include "core/visibility/terrain_gather.hpp"

namespace ts::render {

// The sun's part takes T_b's bands 0..1 (4 coefficients): the bounce is smooth, and against
// Blender Cycles all 9 changed the error by under 0.1% of the radiance (docs/rendering.md).
inline constexpr int kBounceSunCoefficients = 4;

// Speed/accuracy knobs (`--bounces`, `--bounce-directions`, `--bounce-radius`, `--bounce-growth`;
// chart in docs/rendering.md, "Bounced light").
struct BounceSettings {
    int bounces = 1;  // 0, 1 or 2
    // 8 azimuths out to 64 texels in steps growing 1.3x: 11 steps where 32 texels at 1.2x took
    // 10, at the same cost, and under the sun closer to Blender Cycles: what lies beyond the
    // radius is lit as open flat ground, too bright for a slope facing a shaded one across its
    // valley (docs/rendering.md, "Bounced light").
    visibility::TerrainGatherSettings gather{8, 64.0, 1.3};
    // The sun's part (`--bounce-sun`): gathered per frame (bounce_sun_gather.hpp), or through T_b's
    // SH. Against Blender Cycles inside cast shadows: docs/rendering.md, "Bounced light".
    enum class SunPart { gather, sh };
    SunPart sun = SunPart::gather;
};

// Throws ts::InputError on bounces outside 0..2 or a bad gather.
void check_bounce_settings(const BounceSettings& s);

struct BounceInputs {
    const terrain::HeightGrid* grid = nullptr;
    const visibility::HorizonSet* horizons = nullptr;  // over the whole grid (D azimuths)
    const NormalField* normals = nullptr;
    std::span<const float> albedo;    // per texel, grey (what the terrain reflects)
    const float* transfer = nullptr;  // T_d [16][texels], band-corrected (bands 0..2 carry light)
    int coefficients = 9;             // the K leading coefficients of T_d that carry light
    double curvature = 0;             // as the horizons have it (earth_curvature.hpp)
    int threads = 0;
};

// The open flat texel's band-corrected diffuse transfer (the clamped cosine / pi about +z
// projected to bands 0..2): what T_d is for a level texel with nothing above its horizon.
std::array<float, 16> flat_transfer();

// T_b [K][texels] (K = in.coefficients); NaN on void texels; empty with 0 bounces. Rows in parallel.
// With `sun`: also the gather's weights for the sun part per frame (left empty with 0 bounces).
std::vector<float> bounce_transfer(const BounceInputs& in, const BounceSettings& s, BounceSunGather* sun = nullptr);

// The blocked part of a receiver's view, in steradians, cosine-weighted (D azimuths, exact):
// the terrain above its own plane. pi (1 - svf), svf the tilted sky view factor. (Without a
// gather, all of it is far ground.)
double blocked_view(const visibility::HorizonSet& horizons, std::size_t texel, const glm::dvec3& normal);

}  // namespace ts::render
