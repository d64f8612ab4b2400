#include "core/util/angles.hpp"
#include "core/render/frame_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/render/render_backend.hpp"
#include "core/render/transfer.hpp"
#include "core/sh/sh_basis.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::render {
namespace {

constexpr float kInvPi = 1.0f / std::numbers::pi_v<float>;

}  // namespace

FrameRenderer::FrameRenderer(ShadingState& state, const ViewShading& view)
    : state_(state), view_(view), sun_vis_(state.texels(), 0.0f) {
    if (state.diffuse_field()) diffuse_rgb_.resize(state.texels());
    spec_rgb_.resize(state.specular_index().size());
}

void FrameRenderer::render(const light::Sky& sky, const SunState& sun, std::vector<glm::vec3>& out) {
    const Stopwatch t0;
    // The specular texels' radiance projection comes from the same pass over the sky.
    light::SkySh radiance_sh{};
    const light::SkySh sh = diffuse_sky_.project(sky, state_.specular_index().empty() ? nullptr : &radiance_sh);
    const double sh_s = t0.seconds();
    render(sky, sh, radiance_sh, sun, out);
    timings_.sky_s += sh_s;
}

void FrameRenderer::render(const light::Sky& sky, const light::SkySh& sky_sh, const light::SkySh& radiance_sh,
                           const SunState& sun, std::vector<glm::vec3>& out) {
    const std::size_t texels = state_.texels();
    const int threads = state_.options().threads;
    out.resize(texels);
    timings_ = {};
    Stopwatch t0;
    const light::SunDisc disc = sky.sun();
    const glm::vec3 e_sun = disc.irradiance;
    // The disc's top above the astronomical horizon and some light: sweep for its visibility.
    const bool sun_up = (e_sun.x > 0 || e_sun.y > 0 || e_sun.z > 0) &&
                        sun.elevation_deg > -degrees(disc.angular_radius_rad);
    const std::vector<std::uint32_t>& water_index = state_.water_index();
    if (!water_index.empty()) sky_table_.update(sky);
    timings_.sky_s = t0.seconds();

    t0.restart();
    state_.sun_visibility(sun, sun_up, sun_vis_, state_.has_other_sun_shadows() ? &terrain_sun_vis_ : nullptr,
                          state_.options().keep_sun_horizon ? &sun_horizon_ : nullptr);
    timings_.sun_visibility_s = t0.seconds();

    t0.restart();
    const std::vector<std::uint32_t>& spec_index = state_.specular_index();
    if (!spec_index.empty()) {
        // A glossy lobe takes the radiance's projection, not the diffuse fit.
        shade_transfer(view_.t_spec.data(), spec_index.size(), radiance_sh, spec_rgb_.data(), threads);
        if (view_.spec_clamp) view_.spec_clamp->apply(radiance_sh, spec_rgb_.data(), threads);
    }

    const glm::vec3 s = glm::vec3(sun_direction(sun));
    const glm::vec3 e_diffuse = sun_up ? e_sun * kInvPi : glm::vec3(0.0f);
    // The bounce's sun part: gathered from the texels' own sun (bounce_sun_gather.hpp, added with
    // the sky below), or through T_b's SH, the SH basis at the sun (bounce_transfer.hpp).
    const bool gather_bounce = !state_.bounce_sun_gather().empty();
    const float* sh_bounce = gather_bounce || state_.bounce_transfer().empty() ? nullptr : state_.bounce_transfer().data();
    std::array<float, 16> sun_sh{};
    if (sh_bounce && sun_up) {
        const sh::ShVec y = sh::eval(glm::dvec3(s));
        for (int i = 0; i < 16; ++i) sun_sh[std::size_t(i)] = float(y[std::size_t(i)]);
    }
    const DiffuseShading* fused = state_.fused_diffuse();
    // A mesh blocker only removes light: its texels' sky terms are bounded by the terrain's.
    const BlockerSkyClamp* clamp = state_.blocker_sky_clamp();
    // Irradiance / pi added to <T, L>: the sky's light over the horizons, the gathered bounce of the sun.
    const HorizonSkyLight* horizon_sky = state_.horizon_sky();
    const bool add_bounce = gather_bounce && sun_up;
    if (horizon_sky || add_bounce) {
        sky_add_.resize(texels);
        if (horizon_sky)
            horizon_sky->irradiance_over_pi(sky, sky_add_.data(), threads);
        else
            std::fill(sky_add_.begin(), sky_add_.end(), glm::vec3(0.0f));
        if (add_bounce) add_gathered_bounce_sun(s, e_diffuse, threads);
    }
    const glm::vec3* sky_add = horizon_sky || add_bounce ? sky_add_.data() : nullptr;
    // Diffuse sky + sun for every texel, the pass that dominates a frame: fused on the CPU path,
    // the backend's <T_d, L> then a second SoA loop otherwise.
    if (fused) {
        fused->shade(sky_sh, sun_vis_.data(), s, e_diffuse, sun_sh, sky_add, out.data(), threads);
        if (clamp) clamp->apply(sky_sh, out.data(), threads);
    } else {
        state_.diffuse_field()->shade(sky_sh, diffuse_rgb_.data());
        if (sky_add)
            for (std::size_t t = 0; t < texels; ++t) diffuse_rgb_[t] += sky_add[t];
        if (clamp) clamp->apply(sky_sh, diffuse_rgb_.data(), threads);
        const MaterialRaster& m = state_.materials();
        const NormalField& nf = state_.normals();
        const int width = state_.width();
        parallel_rows(state_.height(), threads, width * 16LL, [&](int r0, int r1) {
            const std::size_t b = std::size_t(r0) * width, e = std::size_t(r1) * width;
            const float* nx = nf.x.data();
            const float* ny = nf.y.data();
            const float* nz = nf.z.data();
            const float* ar = m.albedo_r.data();
            const float* ag = m.albedo_g.data();
            const float* ab = m.albedo_b.data();
            const float* vis = sun_vis_.data();
            const glm::vec3* d = diffuse_rgb_.data();
            glm::vec3* o = out.data();
            const std::size_t k_count = std::size_t(kBounceSunCoefficients);
            const std::size_t texels_all = state_.texels();
            for (std::size_t t = b; t < e; ++t) {
                const float cos_s = std::max(0.0f, nx[t] * s.x + ny[t] * s.y + nz[t] * s.z);
                const float v = vis[t];
                float sun_w = (v == v ? v : 0.0f) * cos_s;  // NaN (void) -> no sun
                if (sh_bounce) {  // the bounce's sun part, in units of E_sun / pi
                    float u = 0;
                    for (std::size_t i = 0; i < k_count; ++i) u += sh_bounce[i * texels_all + t] * sun_sh[i];
                    if (u == u) sun_w += u * std::numbers::pi_v<float>;
                }
                // The sky's irradiance clamped at 0 as in the fused pass (diffuse_shading.cpp).
                o[t].x = ar[t] * (std::max(d[t].x, 0.0f) + sun_w * e_diffuse.x);
                o[t].y = ag[t] * (std::max(d[t].y, 0.0f) + sun_w * e_diffuse.y);
                o[t].z = ab[t] * (std::max(d[t].z, 0.0f) + sun_w * e_diffuse.z);
            }
        });
    }
    // Phong sheen on the few texels that have one.
    for (std::size_t k = 0; k < spec_index.size(); ++k) {
        const std::size_t t = spec_index[k];
        const ViewShading::SpecTexel& st = view_.spec[k];
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
    const glm::vec3 disc_radiance = disc.disc_irradiance() / solid_angle;
    for (std::size_t k = 0; k < water_index.size(); ++k) {
        const std::size_t t = water_index[k];
        const glm::vec3 r = view_.water_r[k];
        const float f = view_.water_fresnel[k];
        glm::vec3 reflected = sky_table_.lookup(r) * view_.water_vis[k];
        const float v = sun_vis_[t] == sun_vis_[t] ? sun_vis_[t] : 0.0f;
        if (sun_up && glm::dot(r, s) >= cos_disc) reflected += v * disc_radiance;
        const float cos_s = std::max(0.0f, s.z);
        // The body's irradiance / pi: the fused pass left it in out[t] (albedo 1 for water).
        const glm::vec3 body = fused ? out[t] : diffuse_rgb_[t] + v * cos_s * e_diffuse;
        out[t] = f * reflected + (1 - f) * kWaterAlbedo * body;
    }
    timings_.shading_s = t0.seconds();
}

void FrameRenderer::add_gathered_bounce_sun(const glm::vec3& s, const glm::vec3& e_diffuse, int threads) {
    const std::size_t texels = state_.texels(), width = std::size_t(state_.width());
    const NormalField& nf = state_.normals();
    const BounceSunGather& gather = state_.bounce_sun_gather();
    float* sun_light = gather.sun_values(bounce_scratch_);
    bounce_sun_.resize(texels);
    parallel_rows(state_.height(), threads, state_.width() * 4LL, [&](int r0, int r1) {
        for (std::size_t t = std::size_t(r0) * width, e = std::size_t(r1) * width; t < e; ++t) {
            const float v = sun_vis_[t];
            const float cos_s = nf.x[t] * s.x + nf.y[t] * s.y + nf.z[t] * s.z;
            sun_light[t] = v == v && cos_s > 0 ? v * cos_s : 0.0f;  // NaN (void) -> no sun
        }
    });
    gather.apply(s.z, bounce_sun_.data(), bounce_scratch_, threads);
    parallel_rows(state_.height(), threads, state_.width() * 4LL, [&](int r0, int r1) {
        for (std::size_t t = std::size_t(r0) * width, e = std::size_t(r1) * width; t < e; ++t)
            sky_add_[t] += bounce_sun_[t] * e_diffuse;
    });
}

}  // namespace ts::render
