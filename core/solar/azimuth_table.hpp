#pragma once
// What the sun gives a period from each azimuth, as a function of the horizon that hides it:
// for each azimuth bin and each horizon elevation h on a fine grid, the sums over the period's
// time steps whose sun falls in the bin of (weight) x (visible fraction of the sun's disc above
// h). The weights are the direct beam's energy times the sun's direction (so a texel's beam is
// the dot of its normal with one looked-up vector: the cosine of incidence is exact) and the
// hours. The diffuse sky has its own tables (period_sky.hpp). A texel then looks up its own horizon in each bin:
// the cost does not depend on the number of time steps (docs/insolation.md, "Speed").
//
// Each bin stores only the horizon range where its sums change (from the lowest sun in it
// minus the disc's radius to the highest plus it): below, every sample is visible (the bin's
// total); above, none is.
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace ts::solar {

// What one sample of the sun carries (and what a lookup returns): the beam's energy times the
// sun's direction (Wh/m^2, ENU) and hours of sun.
inline constexpr int kTableValues = 4;
using TableValues = std::array<double, kTableValues>;
// Stored as 4 floats, one vector register per lookup.
inline constexpr int kTableStride = 4;

struct HorizonGrid {
    double first_rad = -0.0174532925199433;  // -1 degree: the lowest horizon a table tells apart
    double step_rad = 0.00174532925199433;   // 0.1 degree (the sun's disc spans 0.53)
};

class AzimuthTable {
public:
    AzimuthTable() = default;
    // bins: azimuth bins over [0, 2 pi), bin j centred on phi = 2 pi j / bins.
    AzimuthTable(int bins, HorizonGrid grid);

    int bins() const { return bins_; }
    const HorizonGrid& grid() const { return grid_; }
    // Adds w times the visible fraction of the sun's disc to acc[0..3], for a horizon at
    // horizon_rad in bin j.
    void add_visible(int bin, float horizon_rad, float w, float* acc) const {
        const int count = count_[std::size_t(bin)];
        if (count == 0) return;
        // Without branches on the horizon (they mispredict texel by texel): the first row is the
        // bin's total (every sun visible) and the last is 0 (none), so a horizon below or above
        // the range clamps onto them.
        const float x = std::clamp((horizon_rad - first_h_) * inv_step_ - float(first_[std::size_t(bin)]), 0.0f,
                                   float(count - 1));
        const int k = std::min(int(x), count - 2);
        const float f = x - float(k);
        const float* a = values_.data() + offset_[std::size_t(bin)] + std::size_t(k) * kTableStride;
        const float wa = w * (1 - f), wb = w * f;
        for (int v = 0; v < kTableStride; ++v) acc[v] += wa * a[v] + wb * a[kTableStride + v];
    }
    // Everything in bin j (any horizon below all its suns).
    const float* total(int bin) const { return total_.data() + std::size_t(bin) * kTableStride; }
    bool empty(int bin) const { return count_[std::size_t(bin)] == 0; }

    // The global irradiation of an open horizontal plane over the period (Wh/m^2): the ground
    // that reflects light to the texels.
    double open_global_wh = 0;

    // Builder side: the samples of one bin, then finish().
    struct Sample {
        double elevation_rad;
        TableValues w;
    };
    void finish_bin(int bin, const std::vector<Sample>& samples, double sun_radius_rad);

    std::size_t bytes() const { return values_.size() * sizeof(float) + total_.size() * sizeof(float); }

private:
    int bins_ = 0;
    HorizonGrid grid_;
    std::vector<int> first_, count_;
    std::vector<std::size_t> offset_;
    std::vector<float> total_, values_;
    float first_h_ = 0, inv_step_ = 1;
};

}  // namespace ts::solar
