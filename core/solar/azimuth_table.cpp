#include "core/solar/azimuth_table.hpp"

#include <algorithm>
#include <cmath>

#include "core/visibility/sun_visibility.hpp"

namespace ts::solar {
namespace {

// The visible fraction of the sun's disc as a function of x = (e - h) / r in [-1, 1]
// (visibility::sun_disc_visible_fraction), tabulated: the tables evaluate it ~10 times per
// sample and latitude band, and linear interpolation between 4097 points errs below 1e-6.
class DiscProfile {
public:
    DiscProfile() {
        for (int i = 0; i < kPoints; ++i)
            f_[std::size_t(i)] = visibility::sun_disc_visible_fraction(0.0, -1.0 + 2.0 * i / (kPoints - 1), 1.0);
    }
    double operator()(double x) const {
        if (x >= 1.0) return 1.0;
        if (x <= -1.0) return 0.0;
        const double u = (x + 1.0) * 0.5 * (kPoints - 1);
        const int i = std::min(kPoints - 2, int(u));
        return f_[std::size_t(i)] + (u - i) * (f_[std::size_t(i + 1)] - f_[std::size_t(i)]);
    }

private:
    static constexpr int kPoints = 4097;
    std::array<double, kPoints> f_{};
};

const DiscProfile& disc_profile() {
    static const DiscProfile profile;  // immutable after its thread-safe initialisation
    return profile;
}

}  // namespace

AzimuthTable::AzimuthTable(int bins, HorizonGrid grid)
    : bins_(bins),
      grid_(grid),
      first_(std::size_t(bins), 0),
      count_(std::size_t(bins), 0),
      offset_(std::size_t(bins), 0),
      total_(std::size_t(bins) * kTableStride, 0.0f),
      first_h_(float(grid.first_rad)),
      inv_step_(float(1.0 / grid.step_rad)) {}

void AzimuthTable::finish_bin(int bin, const std::vector<Sample>& samples, double r) {
    if (samples.empty()) return;
    double lo = samples.front().elevation_rad, hi = lo;
    for (const Sample& s : samples) lo = std::min(lo, s.elevation_rad), hi = std::max(hi, s.elevation_rad);
    const double h0 = grid_.first_rad, dh = grid_.step_rad;
    // Row 0 is below every sun of the bin (its total) and the last above all (0): add_visible
    // clamps onto them. first may be negative (a sun below the grid's first horizon).
    const int first = int(std::floor((lo - r - h0) / dh));
    const int last = std::max(first + 1, int(std::ceil((hi + r - h0) / dh)));
    const int count = last - first + 1;
    std::vector<double> full(std::size_t(count) * kTableValues, 0.0), part(std::size_t(count) * kTableValues, 0.0);
    TableValues sum{};
    const DiscProfile& disc = disc_profile();
    for (const Sample& s : samples) {
        for (int v = 0; v < kTableValues; ++v) sum[std::size_t(v)] += s.w[std::size_t(v)];
        // Thresholds k with h_k <= e - r see the whole disc; those within the disc a part of it.
        const int k_full = std::min(count - 1, int(std::floor((s.elevation_rad - r - h0) / dh)) - first);
        if (k_full >= 0)
            for (int v = 0; v < kTableValues; ++v) full[std::size_t(k_full) * kTableValues + std::size_t(v)] += s.w[std::size_t(v)];
        for (int k = std::max(0, k_full + 1); k < count; ++k) {
            const double h = h0 + (first + k) * dh;
            if (h >= s.elevation_rad + r) break;
            const double f = disc((s.elevation_rad - h) / r);
            for (int v = 0; v < kTableValues; ++v) part[std::size_t(k) * kTableValues + std::size_t(v)] += f * s.w[std::size_t(v)];
        }
    }
    // Whole-disc sums accumulate from the top threshold down.
    for (int k = count - 2; k >= 0; --k)
        for (int v = 0; v < kTableValues; ++v)
            full[std::size_t(k) * kTableValues + std::size_t(v)] += full[std::size_t(k + 1) * kTableValues + std::size_t(v)];
    first_[std::size_t(bin)] = first;
    count_[std::size_t(bin)] = count;
    offset_[std::size_t(bin)] = values_.size();
    for (int k = 0; k < count; ++k) {
        for (int v = 0; v < kTableValues; ++v) {
            const std::size_t i = std::size_t(k) * kTableValues + std::size_t(v);
            values_.push_back(float(full[i] + part[i]));
        }
        for (int v = kTableValues; v < kTableStride; ++v) values_.push_back(0.0f);
    }
    for (int v = 0; v < kTableValues; ++v) total_[std::size_t(bin) * kTableStride + std::size_t(v)] = float(sum[std::size_t(v)]);
}

}  // namespace ts::solar
