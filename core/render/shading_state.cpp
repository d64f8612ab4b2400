#include "core/util/angles.hpp"
#include "core/render/shading_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/geo/azimuth.hpp"
#include "core/render/diffuse_band_correction.hpp"
#include "core/render/horizon_transfer.hpp"
#include "core/render/render_backend.hpp"
#include "core/render/transfer.hpp"
#include "core/material/log_brdf.hpp"
#include "core/visibility/blocker_footprint.hpp"
#include "core/visibility/blocker_log_sh.hpp"
#include "core/visibility/blocker_sun_shadow.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/horizon_sh.hpp"
#include "core/visibility/sun_sweep.hpp"
#include "core/visibility/visibility_backend.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::render {

SunState sun_on_grid(const SunState& true_sun, double grid_north_deg) {
    if (grid_north_deg == 0.0) return true_sun;
    double az = std::fmod(true_sun.azimuth_deg + grid_north_deg, 360.0);
    if (az < 0) az += 360.0;
    return {az, true_sun.elevation_deg};
}

glm::dvec3 sun_direction(const SunState& sun) {
    return geo::enu_direction(geo::azimuth_cw_from_north_to_phi(sun.azimuth_deg),
                              radians(sun.elevation_deg));
}

ShadingState::ShadingState(const terrain::HeightGrid& grid, MaterialRaster materials, NormalField normals,
                           const RendererOptions& options)
    : grid_(grid),
      options_(options),
      texels_(std::size_t(grid.width) * std::size_t(grid.height)),
      materials_(std::move(materials)),
      normals_(std::move(normals)) {}

ShadingState::~ShadingState() = default;

namespace {

// Whether the blockers changed any coefficient of texel k of two [16][n] planes (bit for bit:
// outside the footprints the sum was never made).
bool differs(const float* a, const float* b, std::size_t n, std::size_t k) {
    for (int i = 0; i < 16; ++i)
        if (std::memcmp(a + std::size_t(i) * n + k, b + std::size_t(i) * n + k, sizeof(float)) != 0) return true;
    return false;
}

void gather(const float* from, std::size_t from_n, std::span<const std::uint32_t> index, float* to) {
    const std::size_t n = index.size();
    for (int i = 0; i < 16; ++i)
        for (std::size_t k = 0; k < n; ++k) to[std::size_t(i) * n + k] = from[std::size_t(i) * from_n + index[k]];
}

// What the diffuse pass shades with the sky's light over the horizons: the transfer less the
// terrain's own (the bounce and what blockers change stay). The subtraction's rounding below
// 1e-6 goes: fp16 would keep it as subnormals, slow to convert.
void subtract_own_transfer(float* transfer, const float* own, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
        const float v = transfer[i] - own[i];
        transfer[i] = std::abs(v) < 1e-6f ? 0.0f : v;
    }
}

}  // namespace

void ShadingState::diffuse_transfer(const float* log_sh, std::size_t n, const std::uint32_t* index,
                                    float* out) const {
    if (n == 0) return;
    std::vector<float> axis(n * 3);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t t = index ? index[k] : k;
        axis[3 * k] = normals_.x[t], axis[3 * k + 1] = normals_.y[t], axis[3 * k + 2] = normals_.z[t];
    }
    // Diffuse: the cos/pi lobe about the normal, the same ZH for every texel.
    const sh::LogBrdfTable table(options_.brdf_log_eps);
    const sh::ZhVec zh = table.diffuse();
    const std::array<float, 4> lobe = {float(zh[0]), float(zh[1]), float(zh[2]), float(zh[3])};
    TransferInputs in;
    in.texels = n;
    in.log_visibility = log_sh;
    in.lobe_axis = axis.data();
    in.lobe_log_zh = lobe.data();
    in.uniform_lobe = true;
    in.method = options_.exp_method;
    in.threads = options_.threads;
    if (options_.backend) options_.backend->transfer_vectors(in, out);
    else transfer_vectors(in, out);
    // A terrain texel is open when nothing rises above its own plane: its horizons there, not
    // no visibility at all, are what must give the exact projected cosine.
    if (options_.band_correction)
        correct_diffuse_bands(lobe, in.method, out, n,
                              visibility::level_log_visibility(options_.directions, options_.visibility_log_eps));
}

void ShadingState::blocked_transfer(const float* log_terrain, const float* log_blocked, std::size_t m,
                                    const std::uint32_t* index, const float* t_terrain, float* out) const {
    diffuse_transfer(log_blocked, m, index, out);
    if (!exact_terrain() || m == 0) return;
    std::vector<float> log_only(16 * m);
    diffuse_transfer(log_terrain, m, index, log_only.data());
    for (std::size_t i = 0; i < 16 * m; ++i) out[i] = t_terrain[i] + (out[i] - log_only[i]);
}

void ShadingState::add_bounce(std::size_t n, const std::uint32_t* index, float* t) const {
    if (bounce_.empty()) return;
    const std::size_t k_count = std::size_t(bounce_coefficients());
    for (std::size_t i = 0; i < k_count; ++i)
        for (std::size_t k = 0; k < n; ++k) {
            const float b = bounce_[i * texels_ + (index ? index[k] : k)];
            if (b == b) t[i * n + k] += b;
        }
}

glm::vec3 ShadingState::sky_weight(std::size_t t) const {
    // The fused CPU pass multiplies by the albedo (1 for water: its body pass weights it);
    // the backend's field returns the sky term alone.
    if (options_.backend || materials_.water[t]) return glm::vec3(1.0f);
    return {materials_.albedo_r[t], materials_.albedo_g[t], materials_.albedo_b[t]};
}

void ShadingState::bound_changed(const visibility::TexelRect& rect, const std::vector<std::uint32_t>& changed,
                                 const float* t_blocked, const float* t_terrain) {
    std::vector<glm::vec3> weight(changed.size());
    for (std::size_t k = 0; k < changed.size(); ++k) weight[k] = sky_weight(changed[k]);
    if (!sky_clamp_) sky_clamp_ = std::make_unique<BlockerSkyClamp>(options_.band_correction ? 9 : 16);
    sky_clamp_->replace(rect, grid_.width, changed, t_blocked, t_terrain, weight.data());
}

visibility::TexelRect ShadingState::move_mesh(std::size_t k, blockers::PlacedSpheres placed) {
    if (k >= blockers_.meshes.size()) throw std::out_of_range("ShadingState::move_mesh: no mesh " + std::to_string(k));
    const double min_sine = blockers::min_cap_sine(blockers_.options.min_solid_angle_sr);
    const visibility::TexelRect before = visibility::sky_footprint(grid_, blockers_.meshes[k], min_sine);
    blockers_.meshes[k] = std::move(placed);
    blocker_sun_.reset();  // it keeps per-mesh bounds of the old placement
    const visibility::TexelRect after = visibility::sky_footprint(grid_, blockers_.meshes[k], min_sine);
    visibility::TexelRect rect = before.empty() ? after : before;
    if (!before.empty() && !after.empty())
        rect = {std::min(before.col0, after.col0), std::min(before.row0, after.row0), std::max(before.col1, after.col1),
                std::max(before.row1, after.row1)};
    update_blocked_rect(rect);
    return rect;
}

void ShadingState::recompute_blockers() {
    if (!blockers_.empty()) update_blocked_rect({0, 0, grid_.width, grid_.height});
}

void ShadingState::update_blocked_rect(const visibility::TexelRect& rect) {
    if (rect.empty()) return;
    const int w = rect.col1 - rect.col0, h = rect.row1 - rect.row0;
    const std::size_t n = std::size_t(w) * std::size_t(h);
    std::vector<std::uint32_t> index(n);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c)
            index[std::size_t(r) * std::size_t(w) + std::size_t(c)] =
                std::uint32_t(std::size_t(rect.row0 + r) * std::size_t(grid_.width) + std::size_t(rect.col0 + c));
    std::vector<float> terrain(16 * n);
    gather(terrain_log_sh_.data(), texels_, index, terrain.data());
    std::vector<float> blocked = terrain;
    visibility::add_blocker_log_sh(grid_, {rect.col0, rect.row0, w, h}, blockers_,
                                   visibility::curvature_factor(options_.curvature), options_.threads, blocked.data());
    // The rectangle's transfer is the terrain's, the blocked one where the blockers changed it.
    std::vector<float> t_rect(16 * n);
    if (exact_terrain()) gather(terrain_transfer_.data(), texels_, index, t_rect.data());
    else diffuse_transfer(terrain.data(), n, index.data(), t_rect.data());
    std::vector<std::uint32_t> changed, at;
    for (std::size_t k = 0; k < n; ++k)
        if (differs(blocked.data(), terrain.data(), n, k)) changed.push_back(index[k]), at.push_back(std::uint32_t(k));
    const std::size_t m = changed.size();
    std::vector<float> log_b(16 * m), log_t(16 * m), t_blocked(16 * m), t_terrain(16 * m);
    gather(blocked.data(), n, at, log_b.data());
    gather(terrain.data(), n, at, log_t.data());
    gather(t_rect.data(), n, at, t_terrain.data());
    blocked_transfer(log_t.data(), log_b.data(), m, changed.data(), t_terrain.data(), t_blocked.data());
    add_bounce(n, index.data(), t_rect.data());
    add_bounce(m, changed.data(), t_blocked.data());
    gather(t_rect.data(), n, at, t_terrain.data());
    for (int i = 0; i < 16; ++i)
        for (std::size_t j = 0; j < m; ++j) t_rect[std::size_t(i) * n + at[j]] = t_blocked[std::size_t(i) * m + j];
    bound_changed(rect, changed, t_blocked.data(), t_terrain.data());
    if (horizon_sky_) {
        std::vector<float> own(16 * n);
        gather(terrain_transfer_.data(), texels_, index, own.data());
        subtract_own_transfer(t_rect.data(), own.data(), own.size());
    }
    if (diffuse_) diffuse_->update_rect(grid_.width, rect.col0, rect.row0, w, h, t_rect.data());
    else diffuse_field_->update_rect(grid_.width, rect.col0, rect.row0, w, h, t_rect.data());
}

std::unique_ptr<ShadingState> compute_shading_state(const terrain::HeightGrid& grid, MaterialRaster materials,
                                                    NormalField normals, const RendererOptions& options) {
    auto state = std::make_unique<ShadingState>(grid, std::move(materials), std::move(normals), options);
    ShadingState& s = *state;
    const std::size_t texels = s.texels_;
    // Water is a flat mirror whatever the DEM's noise on a lake says.
    for (std::size_t t = 0; t < texels; ++t)
        if (s.materials_.water[t]) s.normals_.x[t] = 0, s.normals_.y[t] = 0, s.normals_.z[t] = 1;
    const bool with_blockers = options.blockers && !options.blockers->empty();
    if (with_blockers) s.blockers_ = *options.blockers;
    s.options_.blockers = with_blockers ? &s.blockers_ : nullptr;

    Stopwatch t0;
    visibility::VisibilityRequest request;
    request.horizon.directions = options.directions;
    request.horizon.method = visibility::HorizonMethod::exact;
    request.horizon.curvature = options.curvature;
    request.horizon.threads = options.threads;
    request.horizon.progress = options.progress;
    // What the views need: V of the specular texels, the horizons of the water texels.
    for (std::size_t t = 0; t < texels; ++t) {
        if (s.materials_.water[t]) s.water_index_.push_back(std::uint32_t(t));
        else if (s.materials_.ks[t] > 0) s.spec_index_.push_back(std::uint32_t(t));
    }
    // The log-SH is what the blockers, the specular texels and the log-SH transfer need.
    request.log_sh = !s.exact_terrain() || with_blockers || !s.spec_index_.empty();
    request.log_eps = options.visibility_log_eps;
    request.blockers = s.options_.blockers;
    request.keep_terrain_log_sh = with_blockers;
    std::unique_ptr<visibility::VisibilityBackend> own_cpu;
    visibility::VisibilityBackend* vb = options.visibility;
    if (!vb) own_cpu = visibility::make_cpu_visibility_backend(), vb = own_cpu.get();
    visibility::VisibilityResult vis = vb->compute(grid, request);
    s.visibility_path_ = vis.path();
    s.visibility_stages_ = vis.stages;
    s.visibility_s_ = t0.seconds();
    const float* log_sh = vis.log_sh.data();

    t0.restart();
    RenderBackend* backend = options.backend;
    {
        std::vector<float> t_diffuse(16 * texels);
        if (s.exact_terrain())
            horizon_transfer({&vis.horizons, &s.normals_, s.bounce_coefficients(), options.threads}, t_diffuse.data());
        else
            s.diffuse_transfer(log_sh, texels, nullptr, t_diffuse.data());
        // The sky light over the horizons replaces the terrain's own <T, L>: kept to subtract.
        std::vector<float> t_sky_part;
        if (options.sky_light.mode == SkyLightSettings::Mode::horizons && s.exact_terrain()) {
            s.horizon_sky_ = std::make_unique<HorizonSkyLight>(vis.horizons, s.normals_, options.sky_light, options.threads);
            // The planes that carry light (the rest are 0).
            t_sky_part.assign(t_diffuse.begin(), t_diffuse.begin() + std::ptrdiff_t(s.bounce_coefficients() * texels));
        }
        // With blockers: the texels they changed, with their terrain-only transfer.
        std::vector<std::uint32_t> changed;
        std::vector<float> t_terrain;
        if (with_blockers && !vis.terrain_log_sh.empty()) {
            s.terrain_log_sh_.assign(vis.terrain_log_sh.begin(), vis.terrain_log_sh.end());
            const float* terrain = s.terrain_log_sh_.data();
            for (std::size_t t = 0; t < texels; ++t)
                if (differs(log_sh, terrain, texels, t)) changed.push_back(std::uint32_t(t));
            const std::size_t m = changed.size();
            std::vector<float> log_t(16 * m);
            t_terrain.resize(16 * m);
            gather(terrain, texels, changed, log_t.data());
            if (s.exact_terrain()) {
                // t_diffuse is the terrain's own; the changed texels get what the blockers change.
                gather(t_diffuse.data(), texels, changed, t_terrain.data());
                std::vector<float> log_b(16 * m), t_b(16 * m);
                gather(log_sh, texels, changed, log_b.data());
                s.blocked_transfer(log_t.data(), log_b.data(), m, changed.data(), t_terrain.data(), t_b.data());
                s.terrain_transfer_ = t_diffuse;
                for (int i = 0; i < 16; ++i)
                    for (std::size_t k = 0; k < m; ++k) t_diffuse[std::size_t(i) * texels + changed[k]] = t_b[std::size_t(i) * m + k];
            } else {
                s.diffuse_transfer(log_t.data(), m, changed.data(), t_terrain.data());
            }
        }
        {
            // Bounced light from the terrain's own transfer: a mesh blocks the sky above the
            // terrain, not (in this model) the light the terrain under it reflects, and a moved
            // mesh then leaves T_b as it is (move_mesh).
            const Stopwatch tb;
            std::vector<float> terrain_only;
            if (!changed.empty()) {
                terrain_only = t_diffuse;
                for (int i = 0; i < 16; ++i)
                    for (std::size_t k = 0; k < changed.size(); ++k)
                        terrain_only[std::size_t(i) * texels + changed[k]] = t_terrain[std::size_t(i) * changed.size() + k];
            }
            // What the terrain reflects, grey: the albedo's luminance (water: its body's).
            std::vector<float> grey(texels);
            const MaterialRaster& m = s.materials_;
            for (std::size_t t = 0; t < texels; ++t)
                grey[t] = m.water[t] ? kWaterAlbedo
                                     : 0.2126f * m.albedo_r[t] + 0.7152f * m.albedo_g[t] + 0.0722f * m.albedo_b[t];
            BounceInputs bi;
            bi.grid = &grid;
            bi.horizons = &vis.horizons;
            bi.normals = &s.normals_;
            bi.albedo = grey;
            bi.transfer = changed.empty() ? t_diffuse.data() : terrain_only.data();
            bi.coefficients = s.bounce_coefficients();
            bi.curvature = visibility::curvature_factor(options.curvature);
            bi.threads = options.threads;
            const bool gather_sun = options.bounce.sun == BounceSettings::SunPart::gather;
            s.bounce_ = bounce_transfer(bi, options.bounce, gather_sun ? &s.bounce_sun_ : nullptr);
            const bool any = std::any_of(s.bounce_.begin(), s.bounce_.end(), [](float b) { return b != 0 && b == b; });
            if (!any) s.bounce_.clear(), s.bounce_sun_ = {};
            s.add_bounce(texels, nullptr, t_diffuse.data());
            s.bounce_s_ = tb.seconds();
        }
        if (!changed.empty()) {
            const std::size_t m = changed.size();
            std::vector<float> t_blocked(16 * m);
            s.add_bounce(m, changed.data(), t_terrain.data());
            gather(t_diffuse.data(), texels, changed, t_blocked.data());
            s.bound_changed({0, 0, grid.width, grid.height}, changed, t_blocked.data(), t_terrain.data());
        }
        // What the diffuse pass shades: T_d, or with the sky's light over the horizons what that
        // leaves out (in place unless a lightable tile keeps the whole T_d).
        std::vector<float> t_shaded;
        float* t_shade = t_diffuse.data();
        if (!t_sky_part.empty()) {
            if (options.keep_diffuse_transfer) t_shaded = t_diffuse, t_shade = t_shaded.data();
            subtract_own_transfer(t_shade, t_sky_part.data(), t_sky_part.size());
        }
        if (backend) {
            s.diffuse_field_ = backend->keep_transfer(t_shade, texels);
        } else {
            // Water texels get albedo 1 here: their fused result is then the body's irradiance / pi
            // (sky + sun), which the water pass weights by (1 - F) kWaterAlbedo.
            std::vector<float> albedo[3] = {s.materials_.albedo_r, s.materials_.albedo_g, s.materials_.albedo_b};
            for (std::size_t t = 0; t < texels; ++t)
                if (s.materials_.water[t]) albedo[0][t] = albedo[1][t] = albedo[2][t] = 1.0f;
            DiffuseShading::Inputs di;
            di.texels = texels;
            di.transfer = t_shade;
            // Band correction scales band 3 by 0: only bands 0..2 (9 coefficients) carry light.
            di.coefficients = options.band_correction ? 9 : 16;
            di.normal[0] = s.normals_.x.data(), di.normal[1] = s.normals_.y.data(), di.normal[2] = s.normals_.z.data();
            for (int c = 0; c < 3; ++c) di.albedo[c] = albedo[c].data();
            di.precision = options.shading_precision;
            // The bounce's sun part through SH, unless the frames gather it (bounce_sun_gather.hpp).
            di.bounce = s.bounce_.empty() || !s.bounce_sun_.empty() ? nullptr : s.bounce_.data();
            s.diffuse_ = std::make_unique<DiffuseShading>(di);
        }
        if (options.keep_diffuse_transfer) s.kept_transfer_ = std::move(t_diffuse);
    }
    const std::size_t n_spec = s.spec_index_.size();
    s.spec_log_sh_.resize(16 * n_spec);
    for (std::size_t k = 0; k < n_spec; ++k)
        for (int i = 0; i < 16; ++i)
            s.spec_log_sh_[std::size_t(i) * n_spec + k] = log_sh[std::size_t(i) * texels + s.spec_index_[k]];
    if (!s.terrain_log_sh_.empty()) {
        s.spec_terrain_log_sh_.resize(16 * n_spec);
        for (std::size_t k = 0; k < n_spec; ++k)
            for (int i = 0; i < 16; ++i)
                s.spec_terrain_log_sh_[std::size_t(i) * n_spec + k] =
                    s.terrain_log_sh_[std::size_t(i) * texels + s.spec_index_[k]];
    }
    const int d_count = vis.horizons.directions;
    s.water_horizons_.resize(s.water_index_.size() * std::size_t(d_count));
    for (std::size_t k = 0; k < s.water_index_.size(); ++k)
        for (int d = 0; d < d_count; ++d)
            s.water_horizons_[k * std::size_t(d_count) + std::size_t(d)] = vis.horizons.plane(d)[s.water_index_[k]];
    s.transfer_s_ = t0.seconds();
    return state;
}

void ShadingState::sun_visibility(const SunState& sun, bool sun_up, std::vector<float>& out,
                                  std::vector<float>* terrain_only, std::vector<float>* horizon_above_sun) {
    out.resize(texels_);
    if (!sun_up) {
        std::fill(out.begin(), out.end(), 0.0f);
        if (terrain_only) *terrain_only = out;
        if (horizon_above_sun) horizon_above_sun->assign(texels_, float(visibility::kSunHorizonBandRad));
        return;
    }
    if (options_.sun_method == visibility::SunMethod::sweep) {
        if (!sun_sweep_) {
            visibility::SunSweepOptions so;
            so.curvature = options_.curvature;
            so.threads = options_.threads;
            sun_sweep_ = std::make_unique<visibility::SunShadowSweep>(grid_, so);
        }
        sun_sweep_->compute(sun.azimuth_deg, sun.elevation_deg, out, horizon_above_sun);
    } else {
        visibility::SunVisibilityOptions so;
        so.curvature = options_.curvature;
        so.threads = options_.threads;
        out = visibility::sun_visibility(grid_, sun.azimuth_deg, sun.elevation_deg, so, horizon_above_sun);
    }
    const bool others = !blockers_.empty() || bool(options_.outer_sun_shadow);
    std::vector<float> own;
    if (terrain_only) *terrain_only = out;
    if (horizon_above_sun && others) own = out;
    if (!blockers_.empty()) {
        if (!blocker_sun_)
            blocker_sun_ = std::make_unique<visibility::BlockerSunShadow>(
                grid_, blockers_, visibility::curvature_factor(options_.curvature), options_.threads);
        blocker_sun_->apply(sun.azimuth_deg, sun.elevation_deg, out);
    }
    if (options_.outer_sun_shadow) options_.outer_sun_shadow(sun, out);
    if (horizon_above_sun && others) {
        const double radius = visibility::SunSweepOptions{}.sun_radius_rad;
        for (std::size_t t = 0; t < texels_; ++t)
            if (out[t] < own[t])  // NaN compares false: voids keep theirs
                (*horizon_above_sun)[t] = std::max((*horizon_above_sun)[t],
                                                   float(visibility::horizon_above_sun_for_fraction(out[t], radius)));
    }
}

}  // namespace ts::render
