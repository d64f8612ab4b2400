#pragma once
// Radiance per DEM texel under a sun and sky, split into what is done once and what is done
// per frame (relighting is cheap because visibility does not change with the light):
//
// once (constructor):  horizons (exact sweep, D azimuths) -> log-SH visibility V;
//                      diffuse transfer  T_d = exp(V + rot(F_diffuse, n))            (every texel)
//                      specular transfer T_s = exp(V + rot(F_phong(alpha), r))        (texels with ks > 0)
//                      water: mirror direction r, Fresnel F(n.v), V(r) from the horizons
// per frame (render):  sky SH L (project_sky_sh), sky table (water), sun visibility (exact
//                      horizon in the sun's azimuth), then per texel
//   L_out = albedo <T_d, L> + ks <T_s, L>
//         + sun_vis E_sun [albedo/pi max(0, n.s) + ks (alpha+1)/(2 pi) max(0, r.s)^alpha [n.s > 0]]
//   water: F L_sky(r) V(r) + (1 - F) 0.02 <T_d, L> + sun glint F L_sun [r in the disc] + (1 - F) 0.02/pi E_sun n.s
// with v the direction towards the viewer (zenith for a map, the camera for a perspective view)
// and r = 2 (n.v) n - v. The BRDFs are session 2's (docs/rendering.md).
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/light/sky.hpp"
#include "core/render/diffuse_shading.hpp"
#include "core/material/material.hpp"
#include "core/render/sky_table.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/sh/exp_method.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/visibility/horizon_sh.hpp"
#include "core/visibility/sun_visibility.hpp"

namespace ts {
class ProgressBar;
}
namespace ts::visibility {
class SunShadowSweep;
}

namespace ts::render {

class RenderBackend;
class ShadeField;

struct RendererOptions {
    int directions = 32;           // horizon azimuths D for the visibility
    bool curvature = true;         // Earth curvature with refraction (horizons and sun)
    float visibility_log_eps = visibility::kDefaultVisibilityLogEps;
    double brdf_log_eps = -2.995732273553991;  // sh::kDefaultBrdfLogEps
    // scaling_squaring: on an open plane under a uniform sky albedo*<T_d, L> comes out 3% low;
    // hybrid (fast, the visibility default) 19% low, because V + F_diffuse is large (docs/rendering.md).
    // It is a one-time cost here, so accuracy wins.
    sh::ExpMethod exp_method = sh::ExpMethod::scaling_squaring;
    // Band correction of the diffuse transfer: every SH band l of T_d is scaled by c_l / e_l, with
    // c_l the clamped cosine / pi projected to order 4 (c_3 = 0) and e_l what the exponentiation
    // gives for the same lobe with nothing blocking, so an open texel gets exactly the projected
    // clamped cosine. It removes the log-lobe's low bias under a low sun (Grenoble, evening sun at
    // 6.7 deg: radiance rel. RMSE 10.3% -> 4.9% against the reference; docs/accuracy.md).
    // One-time cost: one exponentiation and a scaling pass.
    bool band_correction = true;
    // Where the one-time stages (horizons + log-SH, transfer vectors) and the per-frame sky
    // transfer run (core/render/render_backend.hpp; must outlive the renderer). nullptr: here on
    // the CPU, with the per-frame diffuse pass fused and compact (DiffuseShading); a backend
    // (make_cpu_backend, the Vulkan one) shades <T_d, L> itself and the sun and albedo follow in
    // a second pass.
    RenderBackend* backend = nullptr;
    // CPU path (backend == nullptr): how the per-frame copy of T_d, albedo and normal is stored.
    // half (default): fp16 (normal 16-bit fixed point), 30 B/texel read per frame, radiance
    // within 1e-3 of single; single: fp32, 60 B/texel, float rounding (core/render/diffuse_shading.hpp).
    DiffuseShading::Precision shading_precision = DiffuseShading::Precision::half;
    // Per-frame sun visibility: the sweep (core/visibility/sun_sweep.hpp, built on the first frame
    // and kept) or the exact path (the reference; `--sun-shadows exact`).
    visibility::SunMethod sun_method = visibility::SunMethod::sweep;
    int threads = 0;
    ProgressBar* progress = nullptr;  // advanced per texel and azimuth of the horizon pass
};

// Where the viewer is, per texel: one direction for all (a map: straight up) or one per texel.
struct ViewDirections {
    glm::vec3 uniform{0.0f, 0.0f, 1.0f};
    std::vector<glm::vec3> per_texel;  // empty = uniform
};

// What the sun does this frame (user-facing angles, as sun_position gives them).
struct SunState {
    double azimuth_deg = 180.0;
    double elevation_deg = 45.0;
};

struct FrameTimings {
    double sky_s = 0, sun_visibility_s = 0, shading_s = 0;
};

class FrameRenderer {
public:
    // `grid` must outlive the renderer (its heights are swept for the sun every frame).
    FrameRenderer(const terrain::HeightGrid& grid, MaterialRaster materials, NormalField normals,
                  const ViewDirections& view, const RendererOptions& options = {});
    ~FrameRenderer();

    std::size_t texels() const { return texels_; }
    int width() const { return width_; }
    int height() const { return height_; }
    // One-time cost split: horizons + log-SH, and the transfer vectors.
    double visibility_seconds() const { return visibility_s_; }
    double transfer_seconds() const { return transfer_s_; }
    std::size_t specular_texels() const { return spec_index_.size(); }
    std::size_t water_texels() const { return water_index_.size(); }

    // Radiance of every texel (linear RGB, the sky's units) into `out` (resized once to texels()).
    // `sky` is the sky of this frame (its sun disc gives the sun's irradiance and direction).
    void render(const light::Sky& sky, const SunState& sun, std::vector<glm::vec3>& out);
    // The same with the sky's SH already projected (bench: time the parts apart).
    void render(const light::Sky& sky, const light::SkySh& sky_sh, const SunState& sun, std::vector<glm::vec3>& out);

    // The sun's visible fraction per texel of the last frame (0 when the sun was down).
    const std::vector<float>& sun_visibility() const { return sun_vis_; }
    const FrameTimings& last_timings() const { return timings_; }
    const MaterialRaster& materials() const { return materials_; }
    const NormalField& normals() const { return normals_; }

private:
    void compute_sun_visibility(const SunState& sun, bool sun_up);

    const terrain::HeightGrid& grid_;
    RendererOptions options_;
    int width_ = 0, height_ = 0;
    std::size_t texels_ = 0;
    MaterialRaster materials_;
    NormalField normals_;
    double visibility_s_ = 0, transfer_s_ = 0;

    // Diffuse transfer T_d, kept in one of two forms: the fused compact copy (CPU path) or the
    // backend's ShadeField (then diffuse_rgb_ receives <T_d, L> each frame).
    std::unique_ptr<DiffuseShading> diffuse_;
    std::unique_ptr<ShadeField> diffuse_field_;
    // Specular texels (ks > 0, not water): indices, their transfer [16][n], and what the per-frame
    // sun term reads, copied together (the texels are scattered: one stream, not four gathers).
    struct SpecTexel {
        glm::vec3 normal, mirror;
        float ks, alpha;
    };
    std::vector<std::uint32_t> spec_index_;
    std::vector<float> t_spec_;
    std::vector<SpecTexel> spec_;
    // Water texels: indices, mirror direction, Fresnel reflectance, visibility of r.
    std::vector<std::uint32_t> water_index_;
    std::vector<glm::vec3> water_r_;
    std::vector<float> water_fresnel_, water_vis_;

    // Per-frame scratch, allocated once.
    std::vector<glm::vec3> diffuse_rgb_, spec_rgb_;  // diffuse_rgb_: backend path only
    std::vector<float> sun_vis_;
    std::unique_ptr<visibility::SunShadowSweep> sun_sweep_;  // RendererOptions::sun_method sweep
    SkyTable sky_table_;
    FrameTimings timings_;
};

// The direction towards the sun in ENU from user-facing angles.
glm::dvec3 sun_direction(const SunState& sun);

}  // namespace ts::render
