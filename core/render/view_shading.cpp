#include "core/util/angles.hpp"
#include "core/render/view_shading.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "core/material/fresnel.hpp"
#include "core/render/render_backend.hpp"
#include "core/render/transfer.hpp"
#include "core/material/log_brdf.hpp"

namespace ts::render {
namespace {

glm::vec3 mirror(const glm::vec3& n, const glm::vec3& v) {
    return 2.0f * (n.x * v.x + n.y * v.y + n.z * v.z) * n - v;
}

glm::vec3 normalized(glm::vec3 v) {
    const float len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return len > 0 ? v / len : glm::vec3(0, 0, 1);
}

// Visibility of direction r from a texel's D horizons (linear in azimuth between them),
// softened over +-0.5 degree so the order of texels along a shoreline does not alias.
float horizon_visibility(const float* horizons, int d_count, const glm::vec3& r) {
    double phi = std::atan2(double(r.y), double(r.x));
    if (phi < 0) phi += 2 * std::numbers::pi;
    const double u = phi / (2 * std::numbers::pi) * d_count;
    const int d0 = int(u) % d_count, d1 = (d0 + 1) % d_count;
    const double f = u - std::floor(u);
    const float h0 = horizons[d0], h1 = horizons[d1];
    if (std::isnan(h0) || std::isnan(h1)) return 1.0f;
    const double horizon = h0 + f * (h1 - h0);
    const double el = std::asin(std::clamp(double(r.z), -1.0, 1.0));
    const double soft = radians(0.5);
    return float(std::clamp((el - horizon + soft) / (2 * soft), 0.0, 1.0));
}

}  // namespace

ViewShading compute_view_shading(const ShadingState& state, const ViewDirections& view) {
    ViewShading out;
    auto view_at = [&](std::size_t t) { return view.per_texel.empty() ? view.uniform : view.per_texel[t]; };
    const MaterialRaster& m = state.materials();
    const NormalField& nf = state.normals();
    const RendererOptions& options = state.options();

    // Specular: a Phong lobe about each texel's mirror direction.
    const std::vector<std::uint32_t>& spec_index = state.specular_index();
    if (!spec_index.empty()) {
        const std::size_t n = spec_index.size();
        std::vector<float> axis(3 * n), lobes(4 * n);
        out.spec.resize(n);
        const sh::LogBrdfTable table(options.brdf_log_eps);
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t t = spec_index[k];
            const glm::vec3 nrm{nf.x[t], nf.y[t], nf.z[t]};
            const glm::vec3 r = normalized(mirror(nrm, view_at(t)));
            axis[3 * k] = r.x, axis[3 * k + 1] = r.y, axis[3 * k + 2] = r.z;
            out.spec[k] = {nrm, r, m.ks[t], m.alpha[t]};
            const sh::ZhVec zh = table.phong(m.alpha[t]);
            for (int i = 0; i < 4; ++i) lobes[4 * k + std::size_t(i)] = float(zh[std::size_t(i)]);
        }
        TransferInputs in;
        in.texels = n;
        in.log_visibility = state.specular_log_sh().data();
        in.lobe_axis = axis.data();
        in.lobe_log_zh = lobes.data();
        in.method = options.exp_method;
        in.threads = options.threads;
        out.t_spec.resize(16 * n);
        if (options.backend) options.backend->transfer_vectors(in, out.t_spec.data());
        else transfer_vectors(in, out.t_spec.data());
        // The specular texels the blockers changed: their terrain-only transfer bounds the sky term.
        const std::vector<float>& terrain = state.specular_terrain_log_sh();
        if (!terrain.empty()) {
            const float* blocked = state.specular_log_sh().data();
            std::vector<std::uint32_t> changed;
            for (std::size_t k = 0; k < n; ++k)
                for (int i = 0; i < 16; ++i)
                    if (std::memcmp(blocked + std::size_t(i) * n + k, terrain.data() + std::size_t(i) * n + k,
                                    sizeof(float)) != 0) {
                        changed.push_back(std::uint32_t(k));
                        break;
                    }
            const std::size_t n_changed = changed.size();
            std::vector<float> log_t(16 * n_changed), ax(3 * n_changed), lb(4 * n_changed), t_terrain(16 * n_changed), t_blocked(16 * n_changed);
            for (std::size_t j = 0; j < n_changed; ++j) {
                const std::size_t k = changed[j];
                for (int i = 0; i < 16; ++i) {
                    log_t[std::size_t(i) * n_changed + j] = terrain[std::size_t(i) * n + k];
                    t_blocked[std::size_t(i) * n_changed + j] = out.t_spec[std::size_t(i) * n + k];
                }
                for (int i = 0; i < 3; ++i) ax[3 * j + std::size_t(i)] = axis[3 * k + std::size_t(i)];
                for (int i = 0; i < 4; ++i) lb[4 * j + std::size_t(i)] = lobes[4 * k + std::size_t(i)];
            }
            if (n_changed > 0) {
                TransferInputs tin = in;
                tin.texels = n_changed, tin.log_visibility = log_t.data(), tin.lobe_axis = ax.data(), tin.lobe_log_zh = lb.data();
                if (options.backend) options.backend->transfer_vectors(tin, t_terrain.data());
                else transfer_vectors(tin, t_terrain.data());
            }
            const std::vector<glm::vec3> weight(n_changed, glm::vec3(1.0f));
            out.spec_clamp.emplace(16);
            out.spec_clamp->replace({}, 1, changed, t_blocked.data(), t_terrain.data(), weight.data());
        }
    }

    // Water: the mirror direction, its Fresnel weight and whether the terrain hides it.
    const std::vector<std::uint32_t>& water_index = state.water_index();
    const int d_count = state.directions();
    for (std::size_t k = 0; k < water_index.size(); ++k) {
        const glm::vec3 v = normalized(view_at(water_index[k]));
        const glm::vec3 r = normalized(mirror({0, 0, 1}, v));
        out.water_r.push_back(r);
        out.water_fresnel.push_back(
            float(material::fresnel_dielectric(std::clamp(double(v.z), 0.0, 1.0), 1.0, kWaterIor)));
        out.water_vis.push_back(horizon_visibility(state.water_horizons().data() + k * std::size_t(d_count), d_count, r));
    }
    return out;
}

}  // namespace ts::render
