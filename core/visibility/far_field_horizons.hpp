#pragma once
// The horizons that terrain far from a receiver casts, marched over a coarse copy of the grid:
// what a window's exact sweep lacks when a part of a large grid is shaded on its window alone
// (window_visibility_backend.hpp: a tile level's blocks, a streamed DEM's tiles). Near terrain stays the exact sweep's; terrain farther than
// `start_texels` is read from mean levels whose texel matches the gap between march samples
// (the pyramid method's schedule, pyramid_schedule.hpp), so the march never reads the fine
// grid and the copy it reads starts at the coarsest level the first far sample needs: a few
// per cent of the grid's bytes at most. The sun's march takes a denser schedule than the sky's.
//
//   FarField far(level_grid, {.start_texels = halo});        // once per grid
//   HorizonSet set = compute_horizons(window_grid, ...);     // exact, the window alone
//   far.raise(set, window, core, window_grid, {window.col0, window.row0});  // + terrain beyond
//
// A grid too large for memory is never held whole: a streaming pass computes its mean level
// coarse_shift_for() (terrain::downsample_2x2 on bands of 2^shift rows gives the whole grid's
// level exactly) and its highest height, the far field is built from those, and raise() and
// limit_sun() read receiver heights from the window's own grid.
//
// A receiver's exact horizons cover every direction to at least `start_texels` only if the
// window reaches that far around it: raise() is for receivers at least that far inside the
// window (or next to the grid's edge).
#include <cstddef>
#include <limits>
#include <vector>

#include "core/terrain/height_grid.hpp"
#include "core/terrain/height_pyramid.hpp"
#include "core/visibility/horizon_set.hpp"
#include "core/visibility/pyramid_schedule.hpp"
#include "core/visibility/row_metrics.hpp"

namespace ts::visibility {

struct FarFieldOptions {
    // The far field begins this many grid texels from each receiver.
    double start_texels = 256;
    // Samples per octave of distance beyond it (the pyramid schedules': 2 fast, 4 balanced, ...)
    // for the sky's horizons (every azimuth of every receiver) ...
    int samples_per_octave = 4;
    // ... and for the sun's (one azimuth per receiver, where a shadow's end must be crisp).
    int sun_samples_per_octave = 16;
    bool curvature = true;  // as HorizonOptions::curvature
    int threads = 0;        // building and raising; 0 = one per core
};

// Where a window grid (a rectangle of the far field's grid as a grid of its own) has its
// top-left texel, in the far field's grid.
struct WindowOrigin {
    int col0 = 0, row0 = 0;
};

// One 2x2 step of a grid's row spacing, as its mean level takes it: row r of the coarser level
// spans rows 2r and 2r + 1 (the last row of an odd count twice), its spacing their sum.
void halve_row_spacing(std::vector<double>& dx_m, std::vector<double>& dy_m);

class FarField {
public:
    // Reads `grid` (heights, voids, spacing) now; keeps only its coarse copy and row spacing.
    // Throws ts::InputError for start_texels < 1 or samples_per_octave < 1.
    FarField(const terrain::HeightGrid& grid, const FarFieldOptions& options);

    // The same from a copy of a width0 x height0 grid made elsewhere, for a grid never held
    // whole: `coarse` is the grid's mean level `coarse_shift` (terrain::downsample_2x2 applied
    // coarse_shift times to the heights; its row r's dx_m/dy_m the sums of those of the finer
    // level's rows 2r and 2r + 1, the last row of an odd level counted twice); dx0_m/dy0_m the
    // grid's own row spacing (height0 entries); z_top its highest height (voids skipped): the
    // march's early exit bounds the terrain ahead by it, and a receiver on a peak stands above
    // the coarse copy's highest mean.
    // At coarse_shift_for(options, width0, height0) it equals the far field built on the grid,
    // bit for bit; a finer copy is downsampled further here to the same result. A coarser copy
    // is read as it is: its first far samples then read terrain coarser than their gap asks
    // (the grid's finer level is not there to read).
    // Throws ts::InputError for bad options, or a copy or row spacing of another size.
    FarField(const terrain::HeightGrid& coarse, int coarse_shift, int width0, int height0, std::vector<double> dx0_m,
             std::vector<double> dy0_m, float z_top, const FarFieldOptions& options);

    // The mean level of a width0 x height0 grid the far field reads (its finest): the level a
    // caller streaming the grid computes for the constructor above. Throws as the constructors.
    static int coarse_shift_for(const FarFieldOptions& options, int width0, int height0);

    // Raises the angles of `set` (receivers of a window of the grid whose top-left texel is
    // `origin`) to the far terrain's where that is higher, for the receivers of `receivers`
    // (grid coordinates, inside the set's window). Void receivers (NaN) stay NaN. Receiver
    // heights come from `window` (heights only; its top-left texel is grid texel
    // `window_origin`, and it holds every receiver), so the grid itself need not be in memory.
    void raise(HorizonSet& set, const ReceiverWindow& origin, const ReceiverWindow& receivers,
               const terrain::HeightGrid& window, const WindowOrigin& window_origin) const;
    // The same with the whole grid as the window.
    void raise(HorizonSet& set, const ReceiverWindow& origin, const ReceiverWindow& receivers,
               const terrain::HeightGrid& grid) const;

    // Lowers `vis` (a visible sun fraction per texel of the set's window whose top-left texel
    // is `origin`, width `origin.width`) for the receivers of `receivers` to the part of the
    // sun's disc above the far field's horizon in the sun's azimuth (user degrees: azimuth
    // clockwise from north). NaN stays NaN. Receiver heights as in raise().
    void limit_sun(double azimuth_deg, double elevation_deg, double sun_radius_rad, const ReceiverWindow& origin,
                   const ReceiverWindow& receivers, const terrain::HeightGrid& window,
                   const WindowOrigin& window_origin, float* vis) const;
    // The same with the whole grid as the window.
    void limit_sun(double azimuth_deg, double elevation_deg, double sun_radius_rad, const ReceiverWindow& origin,
                   const ReceiverWindow& receivers, const terrain::HeightGrid& grid, float* vis) const;

    // The highest far-field slope (tan elevation less curvature) at grid texel (col, row) of
    // height z0 towards internal azimuth phi; -infinity where no far terrain lies that way.
    double far_slope(double col, double row, double z0, double phi) const;

    // Grid texels per texel of the coarse copy's finest level (a power of two).
    int coarse_scale() const { return 1 << shift_; }
    int width() const { return width_; }  // of the grid
    int height() const { return height_; }
    std::size_t bytes() const;

private:
    // Throws unless the receivers lie inside the window grid and the window inside the grid.
    void check_window(const ReceiverWindow& receivers, const terrain::HeightGrid& window,
                      const WindowOrigin& window_origin) const;
    // The highest slope along `samples` from (col, row) at height z0. It stops once no farther
    // terrain can beat max(best, floor), or once best reaches `enough` (the sun's march: below
    // `floor` the disc is clear anyway, at `enough` it is hidden).
    double march(const std::vector<PyramidSample>& samples, double col, double row, double z0, double step_c,
                 double step_r, double unit, double floor = -std::numeric_limits<double>::infinity(),
                 double enough = std::numeric_limits<double>::infinity()) const;

    FarFieldOptions options_;
    int width_ = 0, height_ = 0;  // of the grid
    int shift_ = 0;               // the coarse copy is grid level `shift_`
    terrain::HeightPyramid pyramid_;
    RowMetrics metrics_;
    float z_top_ = 0;
    double curvature_ = 0;
    // tau >= start_texels; levels relative to the coarse copy.
    std::vector<PyramidSample> samples_, sun_samples_;
};

}  // namespace ts::visibility
