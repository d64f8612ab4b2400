#include "core/solar/terrain_reflection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/visibility/earth_curvature.hpp"

namespace ts::solar {
namespace {

visibility::TerrainGatherInputs gather_inputs(const ReflectionInputs& in) {
    visibility::TerrainGatherInputs g;
    g.grid = in.grid;
    g.horizons = in.horizons;
    g.normals = in.normals;
    g.channels = in.periods;
    g.values = in.global;
    g.curvature = in.curvature;
    return g;
}

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
    visibility::check_gather_settings(s, "terrain reflection");
}

TexelGather gather_texel(const ReflectionInputs& in, const TerrainReflectionSettings& s, int col, int row) {
    check_reflection_settings(s);
    check_inputs(in);
    TexelGather out;
    out.seen.assign(std::size_t(in.periods), 0.0);
    if (!s.enabled()) return out;
    const visibility::TerrainGatherInputs gi = gather_inputs(in);
    visibility::TerrainGatherer g(gi, s);
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
    const visibility::TerrainGatherInputs gi = gather_inputs(in);
    parallel_rows(grid.height, threads, work_per_row, [&](int r0, int r1) {
        visibility::TerrainGatherer g(gi, s);
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
