#include "core/visibility/terrain_gather.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/util/error.hpp"
#include "core/visibility/fast_atan.hpp"
#include "core/visibility/terrain_gather_weights.hpp"

namespace ts::visibility {
using gather_detail::kHorizonReachedRad;
using gather_detail::weight_above;
using gather_detail::weight_above_horizon;
namespace {

// The largest divisor of D not above the asked number of azimuths.
int sector_count(int asked, int horizon_directions) {
    for (int n = std::min(asked, horizon_directions); n > 1; --n)
        if (horizon_directions % n == 0) return n;
    return 1;
}

// Distances of the march in texels: 1, 1 + g, 1 + g + g^2, ... up to the radius.
std::vector<double> march_distances(const TerrainGatherSettings& s) {
    std::vector<double> t;
    double step = 1, at = 1;
    while (at <= s.radius_texels + 1e-9) {
        t.push_back(at);
        step *= s.growth;
        at += step;
    }
    return t;
}

}  // namespace

double blocked_view(const float* horizons, std::size_t plane_stride, int directions, const double* cos_phi,
                    const double* sin_phi, double nx, double ny, double nz) {
    nz = std::max(nz, 1e-6);
    double blocked = 0;
    for (int d = 0; d < directions; ++d) {
        const double hd = horizons[std::size_t(d) * plane_stride];
        const double a = nx * cos_phi[d] + ny * sin_phi[d];
        const double tan_p = -a / nz;  // the receiver's own plane
        const double hp = fast_atan(tan_p);
        if (!(hd > hp)) continue;  // nothing above the plane this way (or NaN)
        blocked += weight_above(hp, tan_p, a, nz) - weight_above_horizon(hd, a, nz);
    }
    return std::max(0.0, blocked * 2 * kPi / directions);
}

void check_gather_settings(const TerrainGatherSettings& s, const char* what) {
    if (s.directions < 0 || s.directions > 1024)
        throw InputError(std::string(what) + ": " + std::to_string(s.directions) + " directions: must be in 0..1024");
    if (!(s.radius_texels >= 1 && s.radius_texels <= 1024))
        throw InputError(std::string(what) + ": radius " + std::to_string(s.radius_texels) +
                         " texels: must be in [1, 1024]");
    if (!(s.growth >= 1.01 && s.growth <= 4))
        throw InputError(std::string(what) + ": growth " + std::to_string(s.growth) + ": must be in [1.01, 4]");
}

TerrainGatherer::TerrainGatherer(const TerrainGatherInputs& in, const TerrainGatherSettings& s)
    : in_(in), g_(*in.grid), sectors_(sector_count(s.directions, in.horizons->directions)),
      distances_(march_distances(s)) {
    cos_.resize(std::size_t(sectors_));
    sin_.resize(std::size_t(sectors_));
    for (int d = 0; d < sectors_; ++d) {
        const double phi = 2 * kPi * d / sectors_;
        // Snap the axes' rounding (sin(pi) = 1e-16) so their samples stay on grid lines.
        cos_[std::size_t(d)] = std::abs(std::cos(phi)) < 1e-12 ? 0.0 : std::cos(phi);
        sin_[std::size_t(d)] = std::abs(std::sin(phi)) < 1e-12 ? 0.0 : std::sin(phi);
    }
    steps_.resize(std::size_t(sectors_) * distances_.size());
    seen_.resize(std::size_t(in.channels));
    zeros_.assign(std::size_t(in.channels), 0.0f);
}

void TerrainGatherer::set_row(int row) {
    const double dx = g_.dx_m[std::size_t(row)], dy = g_.dy_m[std::size_t(row)];
    const double unit = std::min(dx, dy);
    for (int d = 0; d < sectors_; ++d)
        for (std::size_t k = 0; k < distances_.size(); ++k) {
            const double s = distances_[k] * unit;
            const double dc = cos_[std::size_t(d)] * s / dx, dr = -sin_[std::size_t(d)] * s / dy;  // north = row 0
            const double c0 = std::floor(dc), r0 = std::floor(dr);
            Step& st = steps_[std::size_t(d) * distances_.size() + k];
            st.cell_col = int(c0), st.cell_row = int(r0);
            st.near_col = int(std::lround(dc)), st.near_row = int(std::lround(dr));
            st.fx = float(dc - c0), st.fy = float(dr - r0);
            st.inv_dist = float(1.0 / s);
            st.curvature_drop = float(in_.curvature * s);
        }
}

void TerrainGatherer::gather(int col, int row) {
    std::fill(seen_.begin(), seen_.end(), 0.0);
    seen_weight_ = far_weight_ = 0;
    seen_texels_.clear();
    seen_weights_.clear();
    const int w = g_.width, h = g_.height, channels = in_.channels;
    const std::size_t t = std::size_t(row) * std::size_t(w) + std::size_t(col);
    const std::size_t plane = in_.horizons->texels();
    const int stride = in_.horizons->directions / sectors_;
    const float z0 = g_.z[t];
    const double nx = in_.normals->x[t], ny = in_.normals->y[t];
    const double nz = std::max(double(in_.normals->z[t]), 1e-6);
    const float* z = g_.z.data();
    const float* values = in_.values.data();
    const std::size_t k_count = distances_.size();
    for (int d = 0; d < sectors_; ++d) {
        const double hd = in_.horizons->angle[std::size_t(d * stride) * plane + t];
        const double a = nx * cos_[std::size_t(d)] + ny * sin_[std::size_t(d)];
        double tan_max = -a / nz;  // the receiver's own plane
        double h_max = fast_atan(tan_max);
        if (!(hd > h_max)) continue;  // no terrain above the receiver's plane this way
        double f_max = weight_above(h_max, tan_max, a, nz);
        const Step* st = steps_.data() + std::size_t(d) * k_count;
        for (std::size_t k = 0; k < k_count; ++k, ++st) {
            const int c0 = col + st->cell_col, r0 = row + st->cell_row;
            if (c0 < 0 || r0 < 0 || c0 + 1 >= w || r0 + 1 >= h) break;  // the march left the grid
            const float* p = z + std::size_t(r0) * std::size_t(w) + std::size_t(c0);
            const float top = p[0] + st->fx * (p[1] - p[0]);
            const float bottom = p[w] + st->fx * (p[w + 1] - p[w]);
            const float zs = top + st->fy * (bottom - top);  // NaN next to a void: skipped
            const float tan_s = (zs - z0) * st->inv_dist - st->curvature_drop;
            if (!(tan_s > tan_max)) continue;
            const double h_s = fast_atan(tan_s);
            const double f_s = weight_above(h_s, tan_s, a, nz);
            const double wt = f_max - f_s;
            const std::size_t j = std::size_t(row + st->near_row) * std::size_t(w) + std::size_t(col + st->near_col);
            const float* vs = values + j * std::size_t(channels);
            if (std::isnan(vs[0])) {
                far_weight_ += wt;  // terrain without values (outside a window's receivers)
            } else {
                for (int q = 0; q < channels; ++q) seen_[std::size_t(q)] += wt * vs[q];
                seen_weight_ += wt;
                if (recording_) {
                    const float rw = float(wt) * (in_.record_scale.empty() ? 1.0f : in_.record_scale[j]);
                    // Consecutive samples that read the same nearest texel make one entry.
                    if (!seen_texels_.empty() && seen_texels_.back() == std::uint32_t(j)) {
                        seen_weights_.back() += rw;
                    } else {
                        seen_texels_.push_back(std::uint32_t(j));
                        seen_weights_.push_back(rw);
                    }
                }
            }
            tan_max = tan_s, h_max = h_s, f_max = f_s;
            // Within reach of the exact horizon nothing further can add more than the sliver
            // up to it, which the far weight takes.
            if (h_max >= hd - kHorizonReachedRad) break;
        }
        if (hd > h_max) far_weight_ += f_max - weight_above_horizon(hd, a, nz);
    }
}

}  // namespace ts::visibility
