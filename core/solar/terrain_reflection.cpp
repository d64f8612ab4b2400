#include "core/solar/terrain_reflection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/fast_atan.hpp"

namespace ts::solar {
namespace {

// The largest divisor of D not above the asked number of azimuths.
int sector_count(int asked, int horizon_directions) {
    for (int n = std::min(asked, horizon_directions); n > 1; --n)
        if (horizon_directions % n == 0) return n;
    return 1;
}

// Distances of the march in texels: 1, 1 + g, 1 + g + g^2, ... up to the radius.
std::vector<double> march_distances(const TerrainReflectionSettings& s) {
    std::vector<double> t;
    double step = 1, at = 1;
    while (at <= s.radius_texels + 1e-9) {
        t.push_back(at);
        step *= s.growth;
        at += step;
    }
    return t;
}

// The march stops once its maximum is this close below the exact horizon (0.25 degree).
constexpr double kHorizonReachedRad = 0.0043633;

// One sample of a sector's march, relative to the receiver: the bilinear cell's corner and
// weights for the height, the nearest texel for G, and the distance terms of the slope.
struct Step {
    int cell_col, cell_row;        // upper-left corner of the bilinear cell
    int near_col, near_row;        // nearest texel (the G read)
    float fx, fy;                  // bilinear weights towards +col, +row
    float inv_dist, curvature_drop;  // 1 / s (1/m) and curvature * s (the slope's curvature term)
};

// F(h) (sky_above) from h's tangent (no trig: cos^2 = 1 / (1 + t^2), sin 2h = 2t / (1 + t^2)).
inline double weight_above(double h, double tan_h, double a, double nz) {
    const double c2 = 1.0 / (1.0 + tan_h * tan_h);
    return sky_above(h, 2 * tan_h * c2, c2, a, nz);
}

// F at the exact horizon h in [-pi/2, pi/2], from sin(2h) and cos(2h) by short Taylor series on
// [-pi/2, pi/2] after reduction (errors below 4e-6, far under the sectors' discretisation):
// libm's tan here took a tenth of the gather's time in a profile.
inline double weight_above_horizon(double h, double a, double nz) {
    double x = 2 * h, flip = 1;
    if (x > kPi / 2) x = kPi - x, flip = -1;
    if (x < -kPi / 2) x = -kPi - x, flip = -1;
    const double x2 = x * x;
    const double sin2h = x * (1 + x2 * (-1.0 / 6 + x2 * (1.0 / 120 + x2 * (-1.0 / 5040 + x2 / 362880))));
    const double cos2h =
        flip * (1 + x2 * (-0.5 + x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320 - x2 / 3628800)))));
    return sky_above(h, sin2h, (1 + cos2h) / 2, a, nz);
}

// The gather of one band of rows: the sector directions, the march's distances, and per row
// the samples' offsets (the row's spacing), reused across the row's texels.
class Gatherer {
public:
    Gatherer(const ReflectionInputs& in, const TerrainReflectionSettings& s)
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
        seen_.resize(std::size_t(in.periods));
    }

    int sectors() const { return sectors_; }

    void set_row(int row) {
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

    // The receiver (col, row) of the current row: sums into seen_ and the two weights (in units
    // of the sector width). The receiver must be valid.
    void gather(int col, int row) {
        std::fill(seen_.begin(), seen_.end(), 0.0);
        seen_weight_ = far_weight_ = 0;
        const int w = g_.width, h = g_.height, periods = in_.periods;
        const std::size_t t = std::size_t(row) * std::size_t(w) + std::size_t(col);
        const std::size_t plane = in_.horizons->texels();
        const int stride = in_.horizons->directions / sectors_;
        const float z0 = g_.z[t];
        const double nx = in_.normals->x[t], ny = in_.normals->y[t];
        const double nz = std::max(double(in_.normals->z[t]), 1e-6);
        const float* z = g_.z.data();
        const float* global = in_.global.data();
        const std::size_t k_count = distances_.size();
        for (int d = 0; d < sectors_; ++d) {
            const double hd = in_.horizons->angle[std::size_t(d * stride) * plane + t];
            const double a = nx * cos_[std::size_t(d)] + ny * sin_[std::size_t(d)];
            double tan_max = -a / nz;  // the receiver's own plane
            double h_max = visibility::fast_atan(tan_max);
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
                const double h_s = visibility::fast_atan(tan_s);
                const double f_s = weight_above(h_s, tan_s, a, nz);
                const double wt = f_max - f_s;
                const float* gs = global + (std::size_t(row + st->near_row) * std::size_t(w) +
                                            std::size_t(col + st->near_col)) * std::size_t(periods);
                if (std::isnan(gs[0])) {
                    far_weight_ += wt;  // terrain without a first pass (outside a window's receivers)
                } else {
                    for (int q = 0; q < periods; ++q) seen_[std::size_t(q)] += wt * gs[q];
                    seen_weight_ += wt;
                }
                tan_max = tan_s, h_max = h_s, f_max = f_s;
                // Within reach of the exact horizon nothing further can add more than the sliver
                // up to it, which the isotropic ground fills below.
                if (h_max >= hd - kHorizonReachedRad) break;
            }
            if (hd > h_max) far_weight_ += f_max - weight_above_horizon(hd, a, nz);
        }
    }

    const std::vector<double>& seen() const { return seen_; }
    double seen_weight() const { return seen_weight_; }
    double far_weight() const { return far_weight_; }

private:
    const ReflectionInputs& in_;
    const terrain::HeightGrid& g_;
    int sectors_;
    std::vector<double> distances_, cos_, sin_;
    std::vector<Step> steps_;
    std::vector<double> seen_;
    double seen_weight_ = 0, far_weight_ = 0;
};

void check_inputs(const ReflectionInputs& in) {
    const terrain::HeightGrid& g = *in.grid;
    const std::size_t texels = std::size_t(g.width) * std::size_t(g.height);
    const std::size_t values = texels * std::size_t(std::max(in.periods, 0));
    if (in.horizons->texels() != texels || in.normals->z.size() != texels || in.svf.size() != texels ||
        in.global.size() != values || in.isotropic_reflected.size() != values || in.periods < 1)
        throw InputError("terrain reflection: horizons, normals, view factors and first-pass sums must cover the grid");
}

}  // namespace

void check_reflection_settings(const TerrainReflectionSettings& s) {
    if (s.directions < 0 || s.directions > 1024)
        throw InputError("terrain reflection: " + std::to_string(s.directions) + " directions: must be in 0..1024");
    if (!(s.radius_texels >= 1 && s.radius_texels <= 1024))
        throw InputError("terrain reflection: radius " + std::to_string(s.radius_texels) +
                         " texels: must be in [1, 1024]");
    if (!(s.growth >= 1.01 && s.growth <= 4))
        throw InputError("terrain reflection: growth " + std::to_string(s.growth) + ": must be in [1.01, 4]");
}

TexelGather gather_texel(const ReflectionInputs& in, const TerrainReflectionSettings& s, int col, int row) {
    check_reflection_settings(s);
    check_inputs(in);
    TexelGather out;
    out.seen.assign(std::size_t(in.periods), 0.0);
    if (!s.enabled()) return out;
    Gatherer g(in, s);
    g.set_row(row);
    g.gather(col, row);
    const double dphi = 2 * kPi / g.sectors();
    for (int p = 0; p < in.periods; ++p) out.seen[std::size_t(p)] = g.seen()[std::size_t(p)] * dphi;
    out.seen_weight = g.seen_weight() * dphi;
    out.far_weight = g.far_weight() * dphi;
    return out;
}

std::vector<float> gather_terrain_reflection(const ReflectionInputs& in, const TerrainReflectionSettings& s,
                                             int threads) {
    check_reflection_settings(s);
    check_inputs(in);
    const terrain::HeightGrid& grid = *in.grid;
    const std::size_t periods = std::size_t(in.periods);
    std::vector<float> out(in.global.size(), std::numeric_limits<float>::quiet_NaN());
    if (!s.enabled() || grid.width < 2 || grid.height < 2) {
        std::copy(in.isotropic_reflected.begin(), in.isotropic_reflected.end(), out.begin());
        return out;
    }
    const long long work_per_row = (long long)grid.width * std::min(s.directions, 64) * 16;
    parallel_rows(grid.height, threads, work_per_row, [&](int r0, int r1) {
        Gatherer g(in, s);
        for (int r = r0; r < r1; ++r) {
            g.set_row(r);
            for (int c = 0; c < grid.width; ++c) {
                const std::size_t t = std::size_t(r) * std::size_t(grid.width) + std::size_t(c);
                const float* iso = in.isotropic_reflected.data() + t * periods;
                float* o = out.data() + t * periods;
                if (std::isnan(grid.z[t]) || std::isnan(in.horizons->angle[t]) || std::isnan(in.global[t * periods]))
                    continue;
                if (!(in.svf[t] < 1)) {  // no terrain in view: nothing to gather, the estimate is 0
                    std::copy(iso, iso + periods, o);
                    continue;
                }
                g.gather(c, r);
                const double total = g.seen_weight() + g.far_weight();
                if (!(total > 0)) {  // no terrain above the plane in the gather's azimuths
                    std::copy(iso, iso + periods, o);
                    continue;
                }
                // Scaled to the first pass's blocked part pi (1 - svf) (see the header).
                const double seen_scale = (1.0 - double(in.svf[t])) * in.albedo / total;
                const double far_share = g.far_weight() / total;
                for (std::size_t p = 0; p < periods; ++p)
                    o[p] = float(seen_scale * g.seen()[p] + far_share * double(iso[p]));
            }
        }
    });
    return out;
}

void apply_terrain_reflection(InsolationMap& map, const terrain::HeightGrid& grid,
                              const visibility::HorizonSet& horizons, const render::NormalField& normals,
                              double albedo, const TerrainReflectionSettings& s, int threads,
                              std::span<const float> texel_albedo) {
    check_reflection_settings(s);
    const std::size_t texels = std::size_t(map.width) * std::size_t(map.height);
    const std::size_t periods = std::size_t(map.periods);
    if (!texel_albedo.empty() && texel_albedo.size() != texels)
        throw InputError("terrain reflection: the albedos must cover the grid");
    const bool own_albedo = !texel_albedo.empty();
    // The first pass's isotropic ground took `albedo`; a texel's own replaces it.
    auto iso_scale = [&](std::size_t t) { return own_albedo ? (albedo > 0 ? double(texel_albedo[t]) / albedo : 0.0) : 1.0; };
    if (!s.enabled()) {
        if (!own_albedo) return;
        for (std::size_t p = 0; p < periods; ++p) {
            float* g = map.values.data() + (p * kQuantities + kGlobal) * texels;
            float* r = map.values.data() + (p * kQuantities + kReflected) * texels;
            for (std::size_t t = 0; t < texels; ++t) {
                if (std::isnan(r[t])) continue;
                const float old = r[t];
                r[t] = float(old * iso_scale(t));
                g[t] += r[t] - old;
            }
        }
        return;
    }
    // The first pass's sums interleaved per texel, so that one sample reads every period; with
    // texel albedos, the light leaving the terrain (albedo x global) and an albedo of 1.
    std::vector<float> global(texels * periods), iso(texels * periods);
    for (std::size_t p = 0; p < periods; ++p) {
        const float* g = map.band(int(p), kGlobal);
        const float* r = map.band(int(p), kReflected);
        for (std::size_t t = 0; t < texels; ++t) {
            iso[t * periods + p] = float(r[t] * iso_scale(t));
            // The first pass's global with the texel's own isotropic ground, times its albedo.
            global[t * periods + p] = own_albedo ? (g[t] - r[t] + iso[t * periods + p]) * texel_albedo[t] : g[t];
        }
    }
    ReflectionInputs in;
    in.grid = &grid;
    in.horizons = &horizons;
    in.normals = &normals;
    in.periods = map.periods;
    in.global = global;
    in.isotropic_reflected = iso;
    in.svf = map.svf;
    in.albedo = own_albedo ? 1.0 : albedo;
    in.curvature = visibility::curvature_factor(true);  // as the horizons (HorizonOptions::curvature)
    const std::vector<float> reflected = gather_terrain_reflection(in, s, threads);
    for (std::size_t p = 0; p < periods; ++p) {
        float* g = map.values.data() + (p * kQuantities + kGlobal) * texels;
        const float* beam = map.band(int(p), kBeam);
        const float* diffuse = map.band(int(p), kDiffuse);
        float* r = map.values.data() + (p * kQuantities + kReflected) * texels;
        for (std::size_t t = 0; t < texels; ++t) {
            if (std::isnan(r[t])) continue;
            r[t] = reflected[t * periods + p];
            g[t] = float(double(beam[t]) + double(diffuse[t]) + double(r[t]));
        }
    }
}

}  // namespace ts::solar
