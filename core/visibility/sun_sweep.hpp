#pragma once
// Fast per-frame sun visibility: the sun's visible fraction per texel, as
// sun_visibility() computes it, at a fraction of its cost, for relighting many frames of one grid.
//
// The exact path sweeps lines of constant azimuth keeping the upper convex hull of each line's
// profile, because it needs the whole horizon. For the sun only one elevation e matters, so a
// line keeps a single number instead of a hull: the shadow height S (sun_sweep_shared.h), the
// running maximum of z_k - d_k tan e - curvature drop over the points behind. Per frame:
//  1. far field: lines of constant azimuth (the exact path's: in (col, G) space, one texel
//     apart, sampled at every integer column or row, heights linear between the two texels)
//     carry S over the points at least `delay` steps behind; each line sample's horizon tangent
//     from the occluder that sets S is averaged over the two lines beside each texel, as the
//     exact far field averages its tangents;
//  2. near field: the first near_field_texels are marched from the texel centre exactly as the
//     exact path does (1/4-texel bilinear steps), vectorised along rows with the step offsets
//     shared by the whole row; the horizon is the larger of the two;
//  3. the fraction of the sun's disc above that horizon (sun_disc_visible_fraction).
// Voids (NaN heights) neither cast nor receive (NaN out). Curvature with refraction as in
// earth_curvature.hpp; the receiver window is always the whole grid.
//
// Error against the exact path: the far field keeps the occluder that is highest at the sun's
// centre elevation, not the one with the highest horizon, so inside the disc's band the horizon
// can be slightly low, and its lines carry no blockers between line samples but the segment
// midpoints. Measured (`terrashade bench sun`, 70 sun positions 2..60 deg, 500 px crops): the
// shadow masks (fraction < 0.5) agree to IoU >= 0.995 and the fractions to a mean |diff| <=
// 0.003 per elevation (averaged over 10 azimuths; the worst single position 0.006, Grenoble at
// 2 deg) on every shared DEM but the global 1-degree grid (there a handful of texels, < 0.2%,
// are shadowed at 2-3 deg, so the IoU of those swings, mean |diff| 1e-4).
// Cost: an order of magnitude below the exact path per frame (`terrashade bench sun` measures
// both in one run; docs/accuracy.md has the figures). The near field takes a little over half.
// What makes it so: the hot loops are compiled for x86-64-v3 (AVX2, FMA) besides the baseline
// and picked at load time (target_clones); each sweep step gathers the lines' heights first,
// then advances every line's shadow height in one branch-free, vectorised pass; column sweeps
// keep the far field transposed so the texels of a column are contiguous; the near field skips
// the vector texels when tidying up edges and voids, builds its steps only when the row
// spacing changes, and takes the disc fraction branch-free except inside the disc's band.
#include <cstdint>
#include <vector>

#include "core/terrain/height_grid.hpp"
#include "core/visibility/row_metrics.hpp"
#include "core/visibility/sun_visibility.hpp"

namespace ts::visibility {

struct SunSweepOptions {
    bool curvature = true;             // as SunVisibilityOptions::curvature
    double sun_radius_rad = 0.004654;  // 0.2667 deg
    // Texels marched exactly from the texel centre before the lines take over (the exact path
    // marches 8). The lines beside a texel are up to a texel away sideways, and close to the
    // receiver that is where interpolating them errs most: on Grenoble the masks' worst IoU
    // against the exact path was 0.916 with 2 texels, 0.976 with 4, 0.9965 with 8.
    double near_field_texels = 8.0;
    // The near field is marched in 1/4-texel steps (as the exact path) for this many texels,
    // then in steps of near_field_step_texels (a subset of the exact path's samples). 0.25 by
    // default: 0.5 beyond 2 texels saved ~10% but dropped the worst IoU to 0.987 on Grenoble.
    double near_field_fine_texels = 2.0;
    double near_field_step_texels = 0.25;
    int threads = 0;  // 0 = one per hardware core; the work is split in two stages per frame
};

// Built once per grid (metrics, a transposed copy of the heights, void neighbourhoods), then
// asked for any number of sun positions. The grid must outlive it. compute() is not reentrant.
class SunShadowSweep {
public:
    explicit SunShadowSweep(const terrain::HeightGrid& grid, const SunSweepOptions& options = {});

    // Visible fraction of the sun disc per texel ([row * width + col]); NaN for void texels.
    // The sun as the user sees it: azimuth clockwise from north, elevation in [-90, 90] degrees.
    // With `horizon_above_sun`: also each texel's horizon elevation in the sun's azimuth less
    // the sun's (radians), clamped to kSunHorizonBandRad. The near field then marches for that
    // band, not only the disc's (a little slower). Beyond it the far field's occluder is the one
    // highest at the sun's elevation, not the one with the highest horizon: far from the disc
    // a texel's horizon can be low, but between a lit and a shaded texel the horizon crosses
    // the sun where the exact path's does (median 0, p90 <= 0.13 texel on Grenoble, sun 2-60
    // degrees up: tests/visibility/sun_sweep_test.cpp).
    void compute(double sun_azimuth_deg, double sun_elevation_deg, std::vector<float>& out,
                 std::vector<float>* horizon_above_sun = nullptr);
    std::vector<float> compute(double sun_azimuth_deg, double sun_elevation_deg);

    const SunSweepOptions& options() const { return options_; }
    std::size_t texels() const { return std::size_t(grid_.width) * std::size_t(grid_.height); }

    struct Frame;  // one sun position's sweep geometry (sun_sweep.cpp)

private:
    void far_field(const Frame& f, long n_begin, long n_end, int worker);
    void near_field_rows(const Frame& f, int row_begin, int row_end, float* out) const;

    const terrain::HeightGrid& grid_;
    SunSweepOptions options_;
    RowMetrics metrics_;
    bool has_voids_ = false;   // any NaN height: the lines then check every sample
    double near_m_ = 0;        // near field in metres (as ExactAzimuthSweep)
    std::vector<float> transposed_;          // [col * height + row], for column sweeps
    std::vector<std::uint8_t> near_void_;    // 1 where a void lies within reach of the near field
    std::vector<float> near_top_;            // highest height within the near field's reach
    std::vector<float> far_;  // per texel: far-field horizon tangent ([col * height + row] for column sweeps)
    std::vector<double> g_rows_;  // metrics_.g(row) per row, contiguous for the far field's loops
    double g_step_ = 1;
    std::vector<double> row_at_g_;  // row_of_g(k * g_step_)
    struct LineScratch {  // per line: shadow height, occluder distance, tangent, first step
        std::vector<float> shadow, dist, tangent, ring, step_m;
        std::vector<float> sample_z, sample_ds;  // this step's line heights and step lengths
        std::vector<int> start;
    };
    std::vector<LineScratch> scratch_;  // one per worker
};

}  // namespace ts::visibility
