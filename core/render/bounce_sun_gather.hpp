#pragma once
// The bounced light's sun part, gathered each frame from the light the neighbours really get
// (docs/rendering.md, "Bounced light"). The terrain t sees below its horizons reflects, in the
// sun, B_j = albedo_j E_sun max(0, n_j . s) V_j / pi, V_j the visible share of the sun's disc
// (the frame's own sun shadows, the meshes' too). Through T_b's SH (BounceSettings::SunPart::sh)
// the neighbours' sun is <T_j, Y(s)> over bands 0..1: smooth, blind to their cast shadows, so a
// valley in shadow got its lit slopes' bounce; against Blender Cycles that was most of the
// bounce's error inside cast shadows. Here the sum is made again per frame with the gather's
// own weights (core/visibility/terrain_gather.hpp, recorded once with T_b):
//   b1_t = sum_j w_tj sun_j + far_t max(0, s_z)      (units of E_sun / pi, as V_t max(0, n_t . s))
//   b2_t = sum_j w_tj b1_j                           (the second bounce, with --bounces 2)
// w_tj = (2 / sectors) x the gather's weight x albedo_j, far_t the blocked view the gather did not
// reach over pi x albedo_t (open flat ground, in the sun), sun_j = max(0, n_j . s) V_j.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ts::render {

// The gather reaches at most this many texels from its receiver (BounceSettings checks it).
inline constexpr int kBounceSunGatherReach = 126;

struct BounceSunGather {
    // One terrain texel a receiver sees: where it is from the receiver, in texels, and its weight
    // w_tj = weight x the receiver's scale (16 bits against the receiver's largest weight: a
    // relative 1e-5 of it). 4 bytes: a frame streams them all (20.7 per texel on Grenoble).
    struct Entry {
        std::int8_t dc, dr;
        std::uint16_t weight;
    };
    int bounces = 0;  // 1 or 2 (0: empty)
    int width = 0;    // the grid's
    // Per grid row, its texels' entries in order, kept per row as the one-time pass makes them
    // (rows in parallel), not joined into one array (a copy of them all).
    std::vector<std::vector<Entry>> rows;
    std::vector<std::uint32_t> begin;  // per texel: where its entries start in its row's
    std::vector<float> scale;          // per texel: w_tj = Entry::weight x scale
    std::vector<float> far;            // far_t (0 on voids)

    bool empty() const { return begin.empty(); }
    std::size_t texels() const { return begin.size(); }
    std::size_t entries() const;
    // Texel t's entries from the gather's list (grid indices and weights; t = (col, row)).
    // Throws std::logic_error on a texel beyond kBounceSunGatherReach.
    void set_entries(int col, int row, const std::vector<std::uint32_t>& texel, const std::vector<float>& weight);
    // out[t] = b1_t (+ b2_t), texels() entries; `sun` is sun_j per texel (0 where unknown),
    // `sun_z` the sun direction's up component. `scratch` keeps b1 between the two bounces.
    void apply(const float* sun, float sun_z, float* out, std::vector<float>& scratch, int threads) const;
};

}  // namespace ts::render
