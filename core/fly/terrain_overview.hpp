#pragma once
// What a flight over a DEM too large to hold keeps in memory for the whole flight, made in one
// pass over the DEM read band by band (dem::DemSource), never holding more than a band:
//
//   points     every 2^level-th level-0 texel, voids filled: the terrain the CDLOD levels from
//              `level` up draw (their vertices fall on exactly these texels), and the grid the
//              far terrain is shaded on
//   far mean   the DEM's mean pyramid level far_shift (terrain::downsample_2x2 applied far_shift
//              times, equal to the whole-grid result because the bands are aligned to 2^far_shift
//              rows): the terrain beyond a detail tile's window (visibility::FarField)
//   cdlod      the per-level mesh errors (levels up to `level` from every level-0 texel through a
//              histogram, coarser ones on the points) and the height range of every node of the
//              levels from `level` up; the finer levels' nodes come from the detail tiles
//
// The grid flown over is the DEM cropped so that its last column and row fall on the points
// (width - 1 and height - 1 multiples of 2^level): at most 2^level - 1 edge columns and rows are
// dropped (none for SRTM mosaics, whose sizes are multiples of 1200 or 3600 plus one).
#include <cstdint>
#include <vector>

#include "core/dem/dem.hpp"
#include "core/dem/dem_source.hpp"
#include "core/fly/cdlod_tree.hpp"

namespace ts {
class ProgressBar;
}

namespace ts::fly {

struct TerrainOverviewOptions {
    int level = 3;      // the points' level (>= 1)
    int far_shift = 3;  // the far field's mean level (visibility::FarField::coarse_shift_for)
    CdlodOptions lod;
    int threads = 0;
};

struct TerrainOverview {
    int level = 0;
    int width = 0, height = 0;  // the level-0 grid flown over
    dem::Dem points;            // (width - 1) / 2^level + 1 columns, likewise rows; voids filled
    std::vector<double> dx0_m, dy0_m;  // level-0 row spacing (terrain::metric_view's)
    int far_shift = 0;
    int far_width = 0, far_height = 0;
    std::vector<float> far_mean;       // row-major, NaN where every texel under it is void
    std::vector<double> far_dx_m, far_dy_m;
    double z_top = 0;                  // the highest level-0 height
    std::uint64_t void_texels = 0;
    CdlodSummary cdlod;                // stored_level == level
};

// The level-0 row spacing of a width x height grid with this georef (terrain::metric_view's
// rule, without the heights).
void row_spacing(const geo::Georef& georef, int width, int height, std::vector<double>& dx_m, std::vector<double>& dy_m);

// Reads `source` once, band by band. Throws ts::InputError for a DEM smaller than two points a
// side at this level or with no valid height.
TerrainOverview build_terrain_overview(const dem::DemSource& source, const TerrainOverviewOptions& options,
                                       ProgressBar* progress = nullptr);

// The quantile of a non-negative error from a histogram with 32 bins per octave above 1 mm
// (2.2% resolution, read at the bin's upper edge: never below the exact quantile).
class ErrorHistogram {
public:
    void add(double e);
    void merge(const ErrorHistogram& other);
    double quantile(double q) const;
    double max() const { return max_; }
    std::uint64_t count() const { return count_; }

private:
    static constexpr int kBinsPerOctave = 32;
    static constexpr int kBins = 2 + 32 * kBinsPerOctave;
    std::vector<std::uint64_t> bins_ = std::vector<std::uint64_t>(kBins, 0);
    std::uint64_t count_ = 0;
    double max_ = 0;
};

}  // namespace ts::fly
