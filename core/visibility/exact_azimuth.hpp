#pragma once
// The exact method's work for one azimuth, in two stages that can each be split among threads:
//  1. far field: sweep the lines of constant azimuth (any contiguous range of them), splatting
//     each line sample's far-field horizon tangent into per-texel weighted sums;
//  2. finish: per receiver row, march the near field from the texel centre and store
//     max(far, near) as an angle.
// exact_horizons runs both stages for each of its D azimuths on one thread each;
// exact_horizon_in_azimuth (sun_visibility.hpp) splits one azimuth's lines and rows among
// threads, each with its own hull and sums, added in line order afterwards.
#include <cstddef>
#include <limits>
#include <vector>

#include "core/terrain/height_grid.hpp"
#include "core/visibility/horizon_options.hpp"
#include "core/visibility/profile_hull.hpp"
#include "core/visibility/row_metrics.hpp"

namespace ts::visibility {

// Per-worker scratch over the receiver window: the tent-weighted sums of the far-field horizon
// tangents of the line samples that have a far field, and the tent weight of the samples that
// have none (nothing lies near-field far behind them: their line entered the grid, or left a
// void, less than that before them).
struct FarFieldSums {
    std::vector<float> sum, weight, empty_weight;
    DelayedHull hull;
    // One line sample's tent-weighted tangent into texel i, -infinity for a sample without a far
    // field (every splat goes through here, so the layout of the sums is this struct's business).
    void add(std::size_t i, float w, float slope) {
        if (slope == -std::numeric_limits<float>::infinity()) {
            empty_weight[i] += w;
            return;
        }
        sum[i] += w * slope;
        weight[i] += w;
    }
};

// Whether a texel's far field is the mean of its samples that have one: only where those carry
// at least as much of its tent weight as the samples without one, i.e. where the nearer lines
// have a far field. Beside the grid's (or a void's) upwind edge a texel's own line has none
// while the next line, one spacing away, has; that line's weight there is 0 but for rounding,
// and taking its far field at any weight > 0 would make the texel's horizon hinge on the
// rounding (a texel on the edge facing out would see the terrain of the row behind it).
// The vis_exact_finish.comp shader takes the same decision.
inline bool has_far_field(float weight, float empty_weight) {
    return weight > 0 && weight >= empty_weight;
}

// Which family of lines sweeps azimuth phi and the numbers of the lines that can reach the window.
struct SweepPlan {
    double phi = 0;
    bool along_columns = true;   // sampled at every integer column (else every integer row)
    long n_min = 0, n_max = -1;  // inclusive
    long lines() const { return n_max - n_min + 1; }
};

class ExactAzimuthSweep {
public:
    // `options.window` is resolved here; the grid must outlive the sweep.
    ExactAzimuthSweep(const terrain::HeightGrid& grid, const HorizonOptions& options);

    const ReceiverWindow& window() const { return win_; }
    std::size_t texels() const { return std::size_t(win_.width) * std::size_t(win_.height); }
    SweepPlan plan(double phi) const;
    // Scratch sized for the window, sums zeroed, hull delayed by the near field.
    FarFieldSums make_sums() const;
    // Stage 1 for lines n in [n_begin, n_end) of the plan, adding into `sums` (not cleared).
    void sweep_far_field(const SweepPlan& plan, long n_begin, long n_end, FarFieldSums& sums) const;
    // Stage 2 for window rows [lr_begin, lr_end), from the arrays of a FarFieldSums: the horizon
    // angle (radians) of each receiver into plane[lr * width + lc]; void receivers are left untouched.
    // [band_lo, band_hi] (tangents of elevation): only horizons inside it matter to the caller
    // (the sun's disc), so the near-field march stops once the horizon is known to be above
    // band_hi or cannot rise above band_lo; the stored angle is then exact only in that it stays
    // on the same side of the band. The default band keeps every angle exact.
    void finish_rows(double phi, const float* sum, const float* weight, const float* empty_weight, int lr_begin,
                     int lr_end, float* plane, double band_lo = -std::numeric_limits<double>::infinity(),
                     double band_hi = std::numeric_limits<double>::infinity()) const;

private:
    const terrain::HeightGrid& grid_;
    RowMetrics metrics_;
    ReceiverWindow win_;
    double curvature_;
    int lines_per_texel_;
    double near_m_;
    float z_top_;
    bool simd_lines_;  // HorizonOptions::exact_simd_lines (sweep_lanes.hpp)
    // The near field's early exit needs an upper bound of the heights a receiver's near-field
    // march can read. The grid's top is one; the top of the kTile x kTile tile block around the
    // receiver's tile (3 x 3 tiles) is a much tighter one whenever the march stays inside it
    // (near field + 1 bilinear corner <= kTile texels), and it is exact all the same.
    static constexpr int kTile = 16;
    int tiles_x_ = 0;
    std::vector<float> block_top_;  // [tile row][tile col]; empty = use z_top_
    // Prefix count of rows holding a void: the near field's vectorised path needs void-free rows.
    std::vector<int> void_rows_before_;
    bool voids_in_rows(int r_first, int r_last) const {
        return void_rows_before_[std::size_t(r_last) + 1] != void_rows_before_[std::size_t(r_first)];
    }
    float near_top(int col, int row) const {
        return block_top_.empty() ? z_top_ : block_top_[std::size_t(row / kTile) * tiles_x_ + col / kTile];
    }
};

}  // namespace ts::visibility
