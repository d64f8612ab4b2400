#include "core/render/frame_renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "core/geo/azimuth.hpp"
#include "core/material/fresnel.hpp"
#include "core/render/render_backend.hpp"
#include "core/render/transfer.hpp"
#include "core/material/log_brdf.hpp"
#include "core/util/parallel_for.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/sun_sweep.hpp"
#include "core/visibility/sun_visibility.hpp"

namespace ts::render {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

constexpr float kInvPi = 1.0f / std::numbers::pi_v<float>;

glm::vec3 mirror(const glm::vec3& n, const glm::vec3& v) {
    return 2.0f * (n.x * v.x + n.y * v.y + n.z * v.z) * n - v;
}

glm::vec3 normalized(glm::vec3 v) {
    const float len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return len > 0 ? v / len : glm::vec3(0, 0, 1);
}

// Visibility of direction r from a texel's D horizons (linear in azimuth between them),
// softened over +-0.5 degree so the order of texels along a shoreline does not alias.
float horizon_visibility(const visibility::HorizonSet& set, std::size_t t, const glm::vec3& r) {
    const int d_count = set.directions;
    double phi = std::atan2(double(r.y), double(r.x));
    if (phi < 0) phi += 2 * std::numbers::pi;
    const double u = phi / (2 * std::numbers::pi) * d_count;
    const int d0 = int(u) % d_count, d1 = (d0 + 1) % d_count;
    const double f = u - std::floor(u);
    const float h0 = set.angle[std::size_t(d0) * set.texels() + t], h1 = set.angle[std::size_t(d1) * set.texels() + t];
    if (std::isnan(h0) || std::isnan(h1)) return 1.0f;
    const double horizon = h0 + f * (h1 - h0);
    const double el = std::asin(std::clamp(double(r.z), -1.0, 1.0));
    const double soft = 0.5 * std::numbers::pi / 180.0;
    return float(std::clamp((el - horizon + soft) / (2 * soft), 0.0, 1.0));
}

}  // namespace

glm::dvec3 sun_direction(const SunState& sun) {
    return geo::enu_direction(geo::azimuth_cw_from_north_to_phi(sun.azimuth_deg),
                              sun.elevation_deg * (std::numbers::pi / 180.0));
}

namespace {
// RendererOptions::band_correction: scales each SH band of the diffuse transfer t ([16][texels])
// so that a texel with nothing blocking gets the projected clamped cosine / pi exactly.
void correct_diffuse_bands(const std::array<float, 4>& lobe, const TransferInputs& like, std::vector<float>& t) {
    std::array<float, 16> v0{};
    const std::array<float, 3> z = {0, 0, 1};
    TransferInputs in = like;
    in.texels = 1;
    in.log_visibility = v0.data();
    in.lobe_axis = z.data();
    in.lobe_log_zh = lobe.data();
    in.uniform_lobe = true;
    in.threads = 1;
    std::array<float, 16> e{};
    transfer_vectors(in, e.data());  // about the z axis: the ZH of exp(F) sits at the m = 0 entries
    const double pi = std::numbers::pi;
    const double c[4] = {std::sqrt(pi) / 2 / pi, std::sqrt(pi / 3) / pi, std::sqrt(5 * pi) / 8 / pi, 0.0};
    float scale[4];
    for (int l = 0; l < 4; ++l) scale[l] = l == 3 ? 0.0f : float(c[l] / e[std::size_t(l * l + l)]);
    const std::size_t n = t.size() / 16;
    for (int l = 0; l < 4; ++l)
        for (int m = -l; m <= l; ++m) {
            float* p = t.data() + std::size_t(l * l + l + m) * n;
            for (std::size_t k = 0; k < n; ++k) p[k] *= scale[l];
        }
}
}  // namespace

FrameRenderer::FrameRenderer(const terrain::HeightGrid& grid, MaterialRaster materials, NormalField normals,
                             const ViewDirections& view, const RendererOptions& options)
    : grid_(grid),
      options_(options),
      width_(grid.width),
      height_(grid.height),
      texels_(std::size_t(grid.width) * std::size_t(grid.height)),
      materials_(std::move(materials)),
      normals_(std::move(normals)) {
    // Water is a flat mirror whatever the DEM's noise on a lake says.
    for (std::size_t t = 0; t < texels_; ++t)
        if (materials_.water[t]) normals_.x[t] = 0, normals_.y[t] = 0, normals_.z[t] = 1;

    auto t0 = Clock::now();
    visibility::HorizonOptions ho;
    ho.directions = options_.directions;
    ho.method = visibility::HorizonMethod::exact;
    ho.curvature = options_.curvature;
    ho.threads = options_.threads;
    ho.progress = options_.progress;
    RenderBackend* backend = options_.backend;
    std::vector<float> log_sh;
    const visibility::HorizonSet horizons =
        backend ? backend->horizons_and_log_sh(grid_, ho, options_.visibility_log_eps, log_sh)
                : visibility::compute_horizons(grid_, ho);
    if (!backend) log_sh = visibility::log_sh_raster(horizons, options_.visibility_log_eps, options_.threads);
    visibility_s_ = seconds_since(t0);
    auto transfer = [&](const TransferInputs& in, float* out) {
        if (backend) backend->transfer_vectors(in, out);
        else transfer_vectors(in, out);
    };

    t0 = Clock::now();
    auto view_at = [&](std::size_t t) { return view.per_texel.empty() ? view.uniform : view.per_texel[t]; };
    const sh::LogBrdfTable table(options_.brdf_log_eps);

    // Diffuse: the cos/pi lobe about the normal, the same ZH for every texel.
    {
        std::vector<float> axis(texels_ * 3);
        for (std::size_t t = 0; t < texels_; ++t)
            axis[3 * t] = normals_.x[t], axis[3 * t + 1] = normals_.y[t], axis[3 * t + 2] = normals_.z[t];
        const sh::ZhVec zh = table.diffuse();
        const std::array<float, 4> lobe = {float(zh[0]), float(zh[1]), float(zh[2]), float(zh[3])};
        TransferInputs in;
        in.texels = texels_;
        in.log_visibility = log_sh.data();
        in.lobe_axis = axis.data();
        in.lobe_log_zh = lobe.data();
        in.uniform_lobe = true;
        in.method = options_.exp_method;
        in.threads = options_.threads;
        std::vector<float> t_diffuse(16 * texels_);
        transfer(in, t_diffuse.data());
        if (options_.band_correction) correct_diffuse_bands(lobe, in, t_diffuse);
        if (backend) {
            diffuse_field_ = backend->keep_transfer(t_diffuse.data(), texels_);
            diffuse_rgb_.resize(texels_);
        } else {
            // Water texels get albedo 1 here: their fused result is then the body's irradiance / pi
            // (sky + sun), which the water pass weights by (1 - F) kWaterAlbedo.
            std::vector<float> albedo[3] = {materials_.albedo_r, materials_.albedo_g, materials_.albedo_b};
            for (std::size_t t = 0; t < texels_; ++t)
                if (materials_.water[t]) albedo[0][t] = albedo[1][t] = albedo[2][t] = 1.0f;
            DiffuseShading::Inputs di;
            di.texels = texels_;
            di.transfer = t_diffuse.data();
            // Band correction scales band 3 by 0: only bands 0..2 (9 coefficients) carry light.
            di.coefficients = options_.band_correction ? 9 : 16;
            di.normal[0] = normals_.x.data(), di.normal[1] = normals_.y.data(), di.normal[2] = normals_.z.data();
            for (int c = 0; c < 3; ++c) di.albedo[c] = albedo[c].data();
            di.precision = options_.shading_precision;
            diffuse_ = std::make_unique<DiffuseShading>(di);
        }
    }

    // Specular: a Phong lobe about each texel's mirror direction, only where ks > 0.
    for (std::size_t t = 0; t < texels_; ++t)
        if (!materials_.water[t] && materials_.ks[t] > 0) spec_index_.push_back(std::uint32_t(t));
    if (!spec_index_.empty()) {
        const std::size_t n = spec_index_.size();
        std::vector<float> log_v(16 * n), axis(3 * n), lobes(4 * n);
        spec_.resize(n);
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t t = spec_index_[k];
            for (int i = 0; i < 16; ++i) log_v[std::size_t(i) * n + k] = log_sh[std::size_t(i) * texels_ + t];
            const glm::vec3 nrm{normals_.x[t], normals_.y[t], normals_.z[t]};
            const glm::vec3 r = normalized(mirror(nrm, view_at(t)));
            axis[3 * k] = r.x, axis[3 * k + 1] = r.y, axis[3 * k + 2] = r.z;
            spec_[k] = {nrm, r, materials_.ks[t], materials_.alpha[t]};
            const sh::ZhVec zh = table.phong(materials_.alpha[t]);
            for (int i = 0; i < 4; ++i) lobes[4 * k + std::size_t(i)] = float(zh[std::size_t(i)]);
        }
        TransferInputs in;
        in.texels = n;
        in.log_visibility = log_v.data();
        in.lobe_axis = axis.data();
        in.lobe_log_zh = lobes.data();
        in.method = options_.exp_method;
        in.threads = options_.threads;
        t_spec_.resize(16 * n);
        transfer(in, t_spec_.data());
        spec_rgb_.resize(n);
    }

    // Water: the mirror direction, its Fresnel weight and whether the terrain hides it.
    for (std::size_t t = 0; t < texels_; ++t) {
        if (!materials_.water[t]) continue;
        const glm::vec3 v = normalized(view_at(t));
        const glm::vec3 r = normalized(mirror({0, 0, 1}, v));
        water_index_.push_back(std::uint32_t(t));
        water_r_.push_back(r);
        water_fresnel_.push_back(float(material::fresnel_dielectric(std::clamp(double(v.z), 0.0, 1.0), 1.0, kWaterIor)));
        water_vis_.push_back(horizon_visibility(horizons, t, r));
    }
    transfer_s_ = seconds_since(t0);
    sun_vis_.assign(texels_, 0.0f);
}

FrameRenderer::~FrameRenderer() = default;

void FrameRenderer::compute_sun_visibility(const SunState& sun, bool sun_up) {
    if (!sun_up) {
        std::fill(sun_vis_.begin(), sun_vis_.end(), 0.0f);
        return;
    }
    if (options_.sun_method == visibility::SunMethod::sweep) {
        if (!sun_sweep_) {
            visibility::SunSweepOptions so;
            so.curvature = options_.curvature;
            so.threads = options_.threads;
            sun_sweep_ = std::make_unique<visibility::SunShadowSweep>(grid_, so);
        }
        sun_sweep_->compute(sun.azimuth_deg, sun.elevation_deg, sun_vis_);
        return;
    }
    visibility::SunVisibilityOptions so;
    so.curvature = options_.curvature;
    so.threads = options_.threads;
    sun_vis_ = visibility::sun_visibility(grid_, sun.azimuth_deg, sun.elevation_deg, so);
}

void FrameRenderer::render(const light::Sky& sky, const SunState& sun, std::vector<glm::vec3>& out) {
    const auto t0 = Clock::now();
    const light::SkySh sh = light::project_sky_sh(sky);
    const double sh_s = seconds_since(t0);
    render(sky, sh, sun, out);
    timings_.sky_s += sh_s;
}

void FrameRenderer::render(const light::Sky& sky, const light::SkySh& sky_sh, const SunState& sun,
                           std::vector<glm::vec3>& out) {
    out.resize(texels_);
    timings_ = {};
    auto t0 = Clock::now();
    const light::SunDisc disc = sky.sun();
    const glm::vec3 e_sun = disc.irradiance;
    // The disc's top above the astronomical horizon and some light: sweep for its visibility.
    const bool sun_up = (e_sun.x > 0 || e_sun.y > 0 || e_sun.z > 0) &&
                        sun.elevation_deg > -disc.angular_radius_rad * (180.0 / std::numbers::pi);
    if (!water_index_.empty()) sky_table_.update(sky);
    timings_.sky_s = seconds_since(t0);

    t0 = Clock::now();
    compute_sun_visibility(sun, sun_up);
    timings_.sun_visibility_s = seconds_since(t0);

    t0 = Clock::now();
    if (!spec_index_.empty()) shade_transfer(t_spec_.data(), spec_index_.size(), sky_sh, spec_rgb_.data(), options_.threads);

    const glm::vec3 s = glm::vec3(sun_direction(sun));
    const glm::vec3 e_diffuse = sun_up ? e_sun * kInvPi : glm::vec3(0.0f);
    // Diffuse sky + sun for every texel, the pass that dominates a frame: fused on the CPU path,
    // the backend's <T_d, L> then a second SoA loop otherwise.
    if (diffuse_) {
        diffuse_->shade(sky_sh, sun_vis_.data(), s, e_diffuse, out.data(), options_.threads);
    } else {
        diffuse_field_->shade(sky_sh, diffuse_rgb_.data());
        parallel_rows(height_, options_.threads, width_ * 16LL, [&](int r0, int r1) {
            const std::size_t b = std::size_t(r0) * width_, e = std::size_t(r1) * width_;
            const float* nx = normals_.x.data();
            const float* ny = normals_.y.data();
            const float* nz = normals_.z.data();
            const float* ar = materials_.albedo_r.data();
            const float* ag = materials_.albedo_g.data();
            const float* ab = materials_.albedo_b.data();
            const float* vis = sun_vis_.data();
            const glm::vec3* d = diffuse_rgb_.data();
            glm::vec3* o = out.data();
            for (std::size_t t = b; t < e; ++t) {
                const float cos_s = std::max(0.0f, nx[t] * s.x + ny[t] * s.y + nz[t] * s.z);
                const float v = vis[t];
                const float sun_w = (v == v ? v : 0.0f) * cos_s;  // NaN (void) -> no sun
                o[t].x = ar[t] * (d[t].x + sun_w * e_diffuse.x);
                o[t].y = ag[t] * (d[t].y + sun_w * e_diffuse.y);
                o[t].z = ab[t] * (d[t].z + sun_w * e_diffuse.z);
            }
        });
    }
    // Phong sheen on the few texels that have one.
    for (std::size_t k = 0; k < spec_index_.size(); ++k) {
        const std::size_t t = spec_index_[k];
        const SpecTexel& st = spec_[k];
        const float ks = st.ks, alpha = st.alpha;
        glm::vec3 add = ks * spec_rgb_[k];
        const float cos_s = st.normal.x * s.x + st.normal.y * s.y + st.normal.z * s.z;
        const float r_s = st.mirror.x * s.x + st.mirror.y * s.y + st.mirror.z * s.z;
        const float v = sun_vis_[t];
        if (sun_up && cos_s > 0 && r_s > 0 && v > 0)
            add += (v * ks * (alpha + 1) * 0.5f * kInvPi * std::pow(r_s, alpha)) * e_sun;
        out[t] += add;
    }
    // Water: Fresnel mirror of the tabulated sky (and the sun's disc) over a dark body.
    const float cos_disc = float(std::cos(disc.angular_radius_rad));
    const float solid_angle = float(std::numbers::pi * disc.angular_radius_rad * disc.angular_radius_rad);
    for (std::size_t k = 0; k < water_index_.size(); ++k) {
        const std::size_t t = water_index_[k];
        const glm::vec3 r = water_r_[k];
        const float f = water_fresnel_[k];
        glm::vec3 reflected = sky_table_.lookup(r) * water_vis_[k];
        const float v = sun_vis_[t] == sun_vis_[t] ? sun_vis_[t] : 0.0f;
        if (sun_up && glm::dot(r, s) >= cos_disc) reflected += v * e_sun / solid_angle;
        const float cos_s = std::max(0.0f, s.z);
        // The body's irradiance / pi: the fused pass left it in out[t] (albedo 1 for water).
        const glm::vec3 body = diffuse_ ? out[t] : diffuse_rgb_[t] + v * cos_s * e_diffuse;
        out[t] = f * reflected + (1 - f) * kWaterAlbedo * body;
    }
    timings_.shading_s = seconds_since(t0);
}

}  // namespace ts::render
