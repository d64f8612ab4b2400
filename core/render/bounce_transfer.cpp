#include "core/render/bounce_transfer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"

namespace ts::render {
namespace {

constexpr double kPiD = std::numbers::pi;

// cos and sin of the horizons' D azimuths (horizon_set.hpp's phi_d).
struct AzimuthTable {
    std::vector<double> cos_phi, sin_phi;
    explicit AzimuthTable(int directions) {
        for (int d = 0; d < directions; ++d) {
            cos_phi.push_back(std::cos(visibility::azimuth_rad(d, directions)));
            sin_phi.push_back(std::sin(visibility::azimuth_rad(d, directions)));
        }
    }
};

}  // namespace

void check_bounce_settings(const BounceSettings& s) {
    if (s.bounces < 0 || s.bounces > 2)
        throw InputError("bounces: " + std::to_string(s.bounces) + ": must be 0, 1 or 2");
    visibility::check_gather_settings(s.gather, "bounced light");
    if (s.bounces > 0 && s.sun == BounceSettings::SunPart::gather && s.gather.radius_texels > kBounceSunGatherReach)
        throw InputError("bounced light: the sun's part gathered per frame reaches " +
                         std::to_string(kBounceSunGatherReach) + " texels at most; a wider gather takes it through SH");
}

std::array<float, 16> flat_transfer() {
    // c_l = the clamped cosine / pi's zonal coefficients, as diffuse_band_correction.cpp scales to.
    std::array<float, 16> t{};
    t[0] = float(std::sqrt(kPiD) / 2 / kPiD);
    t[2] = float(std::sqrt(kPiD / 3) / kPiD);
    t[6] = float(std::sqrt(5 * kPiD) / 8 / kPiD);
    return t;
}

double blocked_view(const visibility::HorizonSet& horizons, std::size_t texel, const glm::dvec3& n) {
    const int d_count = horizons.directions;
    const AzimuthTable az(d_count);
    return visibility::blocked_view(horizons.angle.data() + texel, horizons.texels(), d_count, az.cos_phi.data(),
                                    az.sin_phi.data(), n.x, n.y, n.z);
}

std::vector<float> bounce_transfer(const BounceInputs& in, const BounceSettings& s, BounceSunGather* sun) {
    check_bounce_settings(s);
    if (sun) *sun = {};
    if (s.bounces == 0) return {};
    const terrain::HeightGrid& grid = *in.grid;
    const std::size_t texels = std::size_t(grid.width) * std::size_t(grid.height);
    const int k_count = in.coefficients;
    if (k_count < 1 || k_count > 16) throw std::invalid_argument("bounce_transfer: 1..16 coefficients");
    if (!in.transfer || in.albedo.size() != texels || in.horizons->texels() != texels || in.normals->z.size() != texels)
        throw std::invalid_argument("bounce_transfer: inputs must cover the grid");
    const std::size_t K = std::size_t(k_count);
    const std::array<float, 16> flat = flat_transfer();
    std::vector<float> out(K * texels, std::numeric_limits<float>::quiet_NaN());
    auto valid = [&](std::size_t t) { return !std::isnan(grid.z[t]) && !std::isnan(in.horizons->angle[t]) &&
                                             !std::isnan(in.transfer[t]); };

    // Pass 1: the scaled gather of albedo_j T_j, and the far ground.
    std::vector<float> values;
    const bool gather = s.gather.enabled() && grid.width > 1 && grid.height > 1;
    if (gather) {
        values.assign(texels * K, std::numeric_limits<float>::quiet_NaN());
        for (std::size_t t = 0; t < texels; ++t)
            if (valid(t))
                for (std::size_t i = 0; i < K; ++i) values[t * K + i] = in.albedo[t] * in.transfer[i * texels + t];
    }
    visibility::TerrainGatherInputs gi;
    gi.grid = &grid;
    gi.horizons = in.horizons;
    gi.normals = in.normals;
    gi.channels = k_count;
    gi.values = values;
    gi.curvature = in.curvature;
    if (sun) gi.record_scale = in.albedo;  // the sun part's weights are w_tj albedo_j
    const long long work_per_row = (long long)grid.width * (gather ? std::min(s.gather.directions, 64) * 16 : 32);
    const int d_count = in.horizons->directions;
    const AzimuthTable az(d_count);
    // The sun part's weights, per row (bounce_sun_gather.hpp).
    if (sun) *sun = BounceSunGather(s.bounces, grid.width, grid.height);
    constexpr int kLanes = visibility::TerrainGatherer::kChunkLanes;
    static_assert(kLanes == BounceSunGather::kLanes, "the gather's chunks are the sun part's");
    // Bit l: receiver (col0 + l, row) is valid.
    auto lanes_of = [&](int col0, int row) {
        unsigned lanes = 0;
        for (int l = 0; l < kLanes && col0 + l < grid.width; ++l)
            if (valid(std::size_t(row) * std::size_t(grid.width) + std::size_t(col0 + l))) lanes |= 1u << l;
        return lanes;
    };
    parallel_rows(grid.height, in.threads, work_per_row, [&](int r0, int r1) {
        std::unique_ptr<visibility::TerrainGatherer> g;
        if (gather) {
            g = std::make_unique<visibility::TerrainGatherer>(gi, s.gather);
            g->set_recording(sun != nullptr);
        }
        // The seen and far weights add up to the blocked view at the gather's sectors, in units
        // of a sector's width: times dphi / pi for T_b.
        const double coef = g ? 2.0 / g->sectors() : 0.0;
        const float coef_f = float(coef);
        std::vector<BounceSunGather::Writer::ChunkEntry> entries;
        std::optional<BounceSunGather::Writer> sun_rows;
        if (sun) sun_rows.emplace(*sun);
        for (int r = r0; r < r1; ++r) {
            if (g) g->set_row(r);
            for (int col0 = 0; col0 < grid.width; col0 += kLanes) {
                const unsigned lanes = lanes_of(col0, r);
                if (!lanes) continue;
                const std::size_t t0 = std::size_t(r) * std::size_t(grid.width) + std::size_t(col0);
                if (g) g->gather_chunk(col0, r, lanes);
                float far[kLanes] = {};
                for (int l = 0; l < kLanes; ++l) {
                    if (!(lanes >> l & 1u)) continue;
                    const std::size_t t = t0 + std::size_t(l);
                    const double far_sr =
                        g ? g->chunk_far_weight(l) * coef * kPiD
                          : visibility::blocked_view(in.horizons->angle.data() + t, texels, d_count, az.cos_phi.data(),
                                                     az.sin_phi.data(), in.normals->x[t], in.normals->y[t],
                                                     in.normals->z[t]);
                    const double far_l = far_sr / kPiD * in.albedo[t];
                    far[l] = float(far_l);
                    for (std::size_t i = 0; i < K; ++i)
                        out[i * texels + t] = float((g ? coef * g->chunk_seen(l)[i] : 0.0) + far_l * flat[i]);
                }
                if (!sun_rows) continue;
                // The sun part's weights: per step of the march, w_tj = coef x weight x albedo_j.
                entries.clear();
                if (g)
                    for (const visibility::TerrainGatherer::StepWeights& sw : g->chunk_steps()) {
                        const visibility::TerrainGatherer::Offset o = g->step_texel(sw.step);
                        BounceSunGather::Writer::ChunkEntry& e = entries.emplace_back();
                        e.dc = o.col, e.dr = o.row;
                        // The gather recorded weight x albedo_j (record_scale).
                        for (int l = 0; l < kLanes; ++l) e.weight[l] = coef_f * sw.weight[l];
                    }
                sun_rows->add_chunk(col0, r, lanes, entries.data(), entries.size(), far);
            }
        }
        if (sun_rows) sun_rows->finish();
    });
    if (s.bounces < 2 || !gather) return out;

    // Pass 2: the same weights over albedo_j T_b,j (the light the first bounce leaves on the
    // terrain); the flat ground beyond bounces nothing more (nothing blocks its view).
    for (std::size_t t = 0; t < texels; ++t)
        for (std::size_t i = 0; i < K; ++i)
            values[t * K + i] = valid(t) ? in.albedo[t] * out[i * texels + t] : std::numeric_limits<float>::quiet_NaN();
    std::vector<float> second(K * texels, 0.0f);
    parallel_rows(grid.height, in.threads, work_per_row, [&](int r0, int r1) {
        visibility::TerrainGatherer g(gi, s.gather);
        const double coef = 2.0 / g.sectors();
        for (int r = r0; r < r1; ++r) {
            g.set_row(r);
            for (int col0 = 0; col0 < grid.width; col0 += kLanes) {
                const unsigned lanes = lanes_of(col0, r);
                if (!lanes) continue;
                g.gather_chunk(col0, r, lanes);
                for (int l = 0; l < kLanes; ++l) {
                    if (!(lanes >> l & 1u)) continue;
                    const std::size_t t = std::size_t(r) * std::size_t(grid.width) + std::size_t(col0 + l);
                    for (std::size_t i = 0; i < K; ++i) second[i * texels + t] = float(coef * g.chunk_seen(l)[i]);
                }
            }
        }
    });
    for (std::size_t j = 0; j < out.size(); ++j) out[j] += second[j];
    return out;
}

}  // namespace ts::render
