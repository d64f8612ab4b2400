#pragma once
// The gather of what a receiver sees of the terrain below its horizons, shared by the
// insolation's reflected light (core/solar/terrain_reflection.hpp) and the renderer's bounced
// light (core/render/bounce_transfer.hpp): the same march, weights and horizons, two uses.
//
// Per receiver, along a few sector azimuths (a subset of the horizons' D, so the horizon angles
// there are exact) the march goes outwards at geometrically growing distances, keeping the
// highest elevation seen so far (starting at the receiver's own tangent plane: below it is
// behind the receiver). A sample above that maximum covers the elevation interval between them
// with its values (per-texel channels, the nearest texel's). What the exact horizon holds above
// the march's maximum (terrain beyond the radius or between samples) is the far weight. The
// weight of an interval [h0, h1] in a sector is F(h0) - F(h1), F the integral of (n.w) cos(e) de
// from h to pi/2 per radian of azimuth (sky_above): the cosine-weighted solid angle of that
// piece of terrain, in units of the sector's width.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/terrain/height_grid.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/util/angles.hpp"
#include "core/visibility/horizon_set.hpp"

namespace ts::visibility {

// The cosine-weighted sky above elevation h in one azimuth, per radian of azimuth: the integral
// over e from h to pi/2 of (n.w) cos(e), a = n.x cos(phi) + n.y sin(phi). Its callers get sin 2h
// and cos^2 h their own way (libm, a tangent, a series), for the precision and speed they need.
// T may be a vector of lanes, S its element type.
template <class T, class S = T>
inline T sky_above(T h, T sin_2h, T cos2_h, T a, T nz) {
    return a * (S(kPi) / 4 - h / 2 - sin_2h / 4) + nz * cos2_h / 2;
}

// The cosine-weighted solid angle of the terrain above a receiver's own plane, from its horizons
// at `directions` azimuths (horizon_set.hpp's phi_d, their cosines and sines given), in
// steradians: pi (1 - svf), svf the tilted sky view factor. NaN horizons count as open.
double blocked_view(const float* horizons, std::size_t plane_stride, int directions, const double* cos_phi,
                    const double* sin_phi, double nx, double ny, double nz);

// How the march goes (defaults: docs/insolation.md, "Reflected", and docs/rendering.md, "Bounced light").
struct TerrainGatherSettings {
    // Azimuths of the gather; 0: no gather. When it does not divide the horizons' D, the largest
    // divisor of D below it.
    int directions = 16;
    // How far the march looks, texels. Kept well under the 256-texel halo of a tile block's
    // window, so that its core texels see the same terrain in a block as in the whole level.
    double radius_texels = 64;
    // Each step is this many times the last (the first is one texel).
    double growth = 1.2;
    bool enabled() const { return directions > 0; }
};

// Throws ts::InputError (naming `what`) on directions outside [0, 1024], a radius outside
// [1, 1024] texels or a growth outside [1.01, 4].
void check_gather_settings(const TerrainGatherSettings& s, const char* what);

// What the march reads. `values` is [texel * channels + channel] over the grid; a NaN first
// channel marks terrain without values (its weight goes to the far weight).
struct TerrainGatherInputs {
    const terrain::HeightGrid* grid = nullptr;
    const HorizonSet* horizons = nullptr;  // over the whole grid
    const render::NormalField* normals = nullptr;
    int channels = 0;
    std::span<const float> values;
    // Earth curvature as the horizons have it: 1 / (2 R_eff) or 0 (earth_curvature.hpp).
    double curvature = 0;
    // Per texel, a factor of the weights recorded for it (the bounce's albedo); empty: 1.
    std::span<const float> record_scale;
};

// One band of rows' worth of march state: the sector directions, the march's distances, and per
// row the samples' offsets (the row's spacing), reused across the row's texels. One per thread.
class TerrainGatherer {
public:
    TerrainGatherer(const TerrainGatherInputs& in, const TerrainGatherSettings& s);

    int sectors() const { return sectors_; }
    void set_row(int row);
    // The receiver (col, row) of the current row (valid, not void): sums into seen() and the two
    // weights, in units of the sector width (times 2 pi / sectors(): steradians).
    void gather(int col, int row);

    const std::vector<double>& seen() const { return seen_; }  // sum of weight x value, per channel
    double seen_weight() const { return seen_weight_; }
    double far_weight() const { return far_weight_; }

    // The receivers (col0 + l, row), l < kChunkLanes, whose bit l is set in `lanes` (valid, in
    // the grid), marched together in vector lanes: the same sums as gather() in floats (a test
    // holds them together). What each lane saw is chunk_seen(l) and chunk_far_weight(l); with
    // recording on, chunk_steps() lists the steps of the march (sector d's k-th sample: step
    // d x steps() + k) where a lane saw terrain with values, with the weight each lane gave the
    // texel it read there (times record_scale), step_texel(step) from its receiver (the same for a row's receivers).
    static constexpr int kChunkLanes = 8;
    struct StepWeights {
        int step;
        float weight[kChunkLanes];
    };
    void gather_chunk(int col0, int row, unsigned lanes);
    const float* chunk_seen(int lane) const { return chunk_seen_.data() + std::size_t(lane) * seen_.size(); }
    double chunk_far_weight(int lane) const { return chunk_far_[std::size_t(lane)]; }
    const std::vector<StepWeights>& chunk_steps() const { return chunk_steps_; }
    int steps() const { return int(distances_.size()); }
    struct Offset {
        int col, row;
    };
    Offset step_texel(int step) const {
        return {steps_[std::size_t(step)].near_col, steps_[std::size_t(step)].near_row};
    }

    // With recording on, gather() also lists the terrain it saw with values: the texels (grid
    // indices) and their weights (times record_scale), one entry per texel met in a row, so that the same sum can be
    // made again over other per-texel values (the bounce's sun part, per frame: bounce_sun_gather.hpp).
    void set_recording(bool on) { recording_ = on; }
    const std::vector<std::uint32_t>& seen_texels() const { return seen_texels_; }
    const std::vector<float>& seen_weights() const { return seen_weights_; }

private:
    // One sample of a sector's march, relative to the receiver: the bilinear cell's corner and
    // weights for the height, the nearest texel for the values, and the distance terms of the slope.
    struct Step {
        int cell_col, cell_row;          // upper-left corner of the bilinear cell
        int near_col, near_row;          // nearest texel (the values' read)
        float fx, fy;                    // bilinear weights towards +col, +row
        float inv_dist, curvature_drop;  // 1 / s (1/m) and curvature * s (the slope's curvature term)
    };
    const TerrainGatherInputs& in_;
    const terrain::HeightGrid& g_;
    int sectors_;
    std::vector<double> distances_, cos_, sin_;
    std::vector<Step> steps_;
    std::vector<double> seen_;
    std::vector<float> chunk_seen_;  // [lane][channel]
    std::vector<double> chunk_far_;  // [lane]
    std::vector<StepWeights> chunk_steps_;
    std::vector<float> zeros_;  // a row of values for lanes that add nothing
    double seen_weight_ = 0, far_weight_ = 0;
    bool recording_ = false;
    std::vector<std::uint32_t> seen_texels_;
    std::vector<float> seen_weights_;
};

}  // namespace ts::visibility
