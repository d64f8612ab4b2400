#pragma once
// The view-independent part of shading a DEM: everything that depends only on the terrain and
// its materials, computed once (per DEM, or per tile of it) and shared by every view and every
// frame (docs/rendering.md, "What is computed once"):
//
//   horizons (exact sweep, D azimuths) -> log-SH visibility V            (VisibilityBackend)
//   diffuse transfer T_d = exp(V + rot(F_diffuse, n)), band-corrected    (every texel)
//   kept for the views: V of the specular texels (ks > 0), the horizons of the water texels
//   per frame: the sun's visibility per texel (the sun sweep, built on the first frame)
//   with mesh blockers: the terrain's own log-SH, and per texel they change the terrain-only
//   transfer, so each frame's sky term is bounded by it (blocker_sky_clamp.hpp)
//
// What depends on the view (specular and water reflection) is ViewShading (view_shading.hpp);
// a frame is FrameRenderer (frame_renderer.hpp); the picture is a RenderTarget.
//
//   ShadingState state = compute_shading_state(grid, materials, normals, options);
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/blockers/placed_spheres.hpp"
#include "core/render/blocker_sky_clamp.hpp"
#include "core/render/bounce_transfer.hpp"
#include "core/render/diffuse_shading.hpp"
#include "core/render/horizon_sky_light.hpp"
#include "core/material/material.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/sh/exp_method.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/visibility/horizon_sh.hpp"
#include "core/visibility/sun_visibility.hpp"
#include "core/visibility/visibility_backend.hpp"

namespace ts {
class ProgressBar;
}
namespace ts::blockers {
struct SphereBlockers;
}
namespace ts::visibility {
class BlockerSunShadow;
class SunShadowSweep;
class VisibilityBackend;
}  // namespace ts::visibility

namespace ts::render {

class RenderBackend;
class ShadeField;

// What the sun does this frame: degrees above the horizon, and clockwise from north as the
// grid sees it. On geographic and Web Mercator grids that is true north (sun_position's
// azimuth); on a projected grid north lies elsewhere (Georef::grid_azimuth_of_north_deg), and
// sun_on_grid turns a true azimuth onto it.
struct SunState {
    double azimuth_deg = 180.0;
    double elevation_deg = 45.0;
};

// The sun of true azimuth `true_sun.azimuth_deg` on a grid whose true north points at
// `grid_north_deg`: azimuth + grid_north_deg, in [0, 360).
SunState sun_on_grid(const SunState& true_sun, double grid_north_deg);

struct RendererOptions {
    int directions = 32;           // horizon azimuths D for the visibility
    bool curvature = true;         // Earth curvature with refraction (horizons and sun)
    float visibility_log_eps = visibility::kDefaultVisibilityLogEps;
    double brdf_log_eps = -2.995732273553991;  // sh::kDefaultBrdfLogEps
    // scaling_squaring: on an open plane under a uniform sky albedo*<T_d, L> comes out 3% low;
    // hybrid (fast, the visibility default) 19% low, because V + F_diffuse is large (docs/rendering.md).
    // It is a one-time cost here, so accuracy wins.
    sh::ExpMethod exp_method = sh::ExpMethod::scaling_squaring;
    // The terrain's own diffuse transfer: projected exactly from its horizons (horizon_transfer.hpp;
    // the default: no sky leaks through the log floor, against Blender Cycles' overcast valleys
    // docs/accuracy.md) or the log-SH path's exp(V + F) (`--terrain-transfer log-sh`, what it was
    // before). Mesh blockers change the exact transfer by what they change in the log-SH one.
    enum class TerrainTransfer { exact, log_sh };
    TerrainTransfer terrain_transfer = TerrainTransfer::exact;
    // Band correction of the diffuse transfer (the log-SH path's): every SH band l of T_d is scaled by c_l / e_l, with
    // c_l the clamped cosine / pi projected to order 4 (c_3 = 0) and e_l what the exponentiation
    // gives for the same lobe with nothing blocking, so an open texel gets exactly the projected
    // clamped cosine. It removes the log-lobe's low bias under a low sun (docs/accuracy.md).
    // One-time cost: one exponentiation and a scaling pass.
    bool band_correction = true;
    // The terrain's sky light: integrated over each texel's horizons in sectors of azimuth
    // (horizons, the default; with the exact terrain transfer only: the log-SH one falls back
    // to sh), the bounce and the mesh blockers still in SH; or all through SH, <T_d, L> (sh).
    // horizon_sky_light.hpp. The sky a frame takes should be sky_for(sky, sky_light).
    SkyLightSettings sky_light;
    // Where horizons and log-SH are computed (core/visibility/visibility_backend.hpp; must
    // outlive the state). nullptr: the CPU.
    visibility::VisibilityBackend* visibility = nullptr;
    // Where the transfer vectors and the per-frame sky transfer run (render_backend.hpp; must
    // outlive the state). nullptr: here on the CPU, with the per-frame diffuse pass fused and
    // compact (DiffuseShading); a backend (make_cpu_backend, the Vulkan one) shades <T_d, L>
    // itself and the sun and albedo follow in a second pass.
    RenderBackend* backend = nullptr;
    // CPU path (backend == nullptr): how the per-frame copy of T_d, albedo and normal is stored.
    // half (default): fp16 (normal 16-bit fixed point), 30 B/texel read per frame, radiance
    // within 1e-3 of single; single: fp32, 60 B/texel, float rounding (diffuse_shading.hpp).
    DiffuseShading::Precision shading_precision = DiffuseShading::Precision::half;
    // Per-frame sun visibility: the sweep (core/visibility/sun_sweep.hpp, built on the first frame
    // and kept) or the exact path (the reference; `--sun-shadows exact`).
    visibility::SunMethod sun_method = visibility::SunMethod::sweep;
    // Mesh blockers over the grid (must outlive the state): their sphere log-SH joins the
    // visibility (through the backend's request), their sun shadows multiply each frame's sun
    // visibility. nullptr or empty: none. The state keeps its own copy (move_mesh changes it).
    const blockers::SphereBlockers* blockers = nullptr;
    // Terrain beyond the grid that shades it from the sun (a block of a larger level: the far
    // field beyond its window, core/tiles/shade_source.cpp): lowers each frame's sun visibility
    // after the grid's own shadows. Empty: the grid is all the terrain there is.
    std::function<void(const SunState&, std::vector<float>&)> outer_sun_shadow;
    // Light bounced off the terrain (bounce_transfer.hpp): its sky part joins T_d, its sun part
    // is added per frame. 0 bounces: direct light only (the terrain's far flat ground remains).
    BounceSettings bounce;
    // Keep a float copy of the diffuse transfer T_d [16][texels] (kept_diffuse_transfer): what a
    // lightable tile stores so that a browser relights it (core/tiles/lightable_style.cpp).
    bool keep_diffuse_transfer = false;
    // Keep each frame's horizon in the sun's azimuth (FrameRenderer::sun_horizon): what a view
    // interpolates between texels to place a shadow's edge inside them (the flythrough).
    bool keep_sun_horizon = false;
    int threads = 0;
    ProgressBar* progress = nullptr;  // advanced per texel and azimuth of the horizon pass
};

class ShadingState {
public:
    // Use compute_shading_state(); this constructor only takes the parts.
    ShadingState(const terrain::HeightGrid& grid, MaterialRaster materials, NormalField normals,
                 const RendererOptions& options);
    ~ShadingState();
    ShadingState(const ShadingState&) = delete;
    ShadingState& operator=(const ShadingState&) = delete;

    const terrain::HeightGrid& grid() const { return grid_; }
    const RendererOptions& options() const { return options_; }
    int width() const { return grid_.width; }
    int height() const { return grid_.height; }
    std::size_t texels() const { return texels_; }
    const MaterialRaster& materials() const { return materials_; }
    const NormalField& normals() const { return normals_; }
    // One-time cost split: horizons + log-SH, and the diffuse transfer.
    double visibility_seconds() const { return visibility_s_; }
    double transfer_seconds() const { return transfer_s_; }
    double bounce_seconds() const { return bounce_s_; }  // part of transfer_seconds()
    // Where the horizons were computed ("cpu" or the Vulkan device's name), and every stage of
    // the visibility with where it ran.
    const std::string& visibility_path() const { return visibility_path_; }
    const std::vector<visibility::VisibilityStage>& visibility_stages() const { return visibility_stages_; }

    // Diffuse transfer in one of two forms: the fused compact copy (CPU path) or the backend's
    // field (then the frame adds the sun and albedo in a second pass).
    const DiffuseShading* fused_diffuse() const { return diffuse_.get(); }
    ShadeField* diffuse_field() const { return diffuse_field_.get(); }

    // Specular texels (ks > 0, not water) and their log-SH visibility [16][n].
    const std::vector<std::uint32_t>& specular_index() const { return spec_index_; }
    const std::vector<float>& specular_log_sh() const { return spec_log_sh_; }
    // With mesh blockers: the same texels' terrain-only log-SH [16][n] (else empty).
    const std::vector<float>& specular_terrain_log_sh() const { return spec_terrain_log_sh_; }
    // Water texels and their D horizons [texel-in-list * D + d] (radians).
    const std::vector<std::uint32_t>& water_index() const { return water_index_; }
    const std::vector<float>& water_horizons() const { return water_horizons_; }
    int directions() const { return options_.directions; }
    // The bounced light's transfer T_b [K][texels] (bounce_transfer.hpp; K = bounce_coefficients()),
    // already added to T_d for the sky; the frames add its sun part. Empty when it is zero everywhere.
    const std::vector<float>& bounce_transfer() const { return bounce_; }
    int bounce_coefficients() const { return options_.band_correction ? 9 : 16; }
    // The weights that gather the bounce's sun part per frame (BounceSettings::SunPart::gather),
    // else empty: then the frames take it from T_b's SH.
    const BounceSunGather& bounce_sun_gather() const { return bounce_sun_; }
    // T_d [16][texels] when RendererOptions::keep_diffuse_transfer, else empty.
    const std::vector<float>& kept_diffuse_transfer() const { return kept_transfer_; }

    // The sun's visible fraction per texel (0 everywhere when `sun_up` is false) into `out`
    // (texels() entries): the terrain's, times the mesh blockers' in their footprints (and an
    // outer shadow's); `terrain_only`, when given, gets the terrain's alone. The sweep is built
    // on the first call and kept.
    // `horizon_above_sun`, when given, gets each texel's horizon in the sun's azimuth less the
    // sun's elevation (visibility::kSunHorizonBandRad about the sun, clamped; +band with the
    // sun down), made to agree with `out` where other shadows darkened a texel.
    void sun_visibility(const SunState& sun, bool sun_up, std::vector<float>& out,
                        std::vector<float>* terrain_only = nullptr, std::vector<float>* horizon_above_sun = nullptr);
    // Whether anything but the grid's own terrain shades the sun (meshes, an outer shadow).
    bool has_other_sun_shadows() const { return !blockers_.empty() || bool(options_.outer_sun_shadow); }
    bool has_outer_sun_shadow() const { return bool(options_.outer_sun_shadow); }

    // Mesh blockers: the state's copy of them, and the bound on the sky term of the texels
    // they change (null without blockers). FrameRenderer applies it after the diffuse pass.
    const blockers::SphereBlockers& blockers() const { return blockers_; }
    const BlockerSkyClamp* blocker_sky_clamp() const { return sky_clamp_.get(); }
    // The sky light over the horizons (SkyLightSettings::Mode::horizons), else null: each
    // frame adds its E / pi to what the diffuse pass makes of T_d - T_terrain.
    const HorizonSkyLight* horizon_sky() const { return horizon_sky_.get(); }

    // Mesh k of the blockers moves to `placed` (a moving mesh, relight --mesh-path): in the
    // bounding rectangle of its old and new sky footprints the terrain's log-SH is restored,
    // every mesh's spheres added again, and the diffuse transfer, its copy for the frames and
    // the sky bound recomputed; nothing outside that rectangle changes. The sun shadows follow
    // on the next sun_visibility. The specular texels' sheen keeps the first placement's
    // visibility. Returns the rectangle. Throws std::out_of_range for a bad k.
    visibility::TexelRect move_mesh(std::size_t k, blockers::PlacedSpheres placed);
    // The same recompute over the whole grid (what move_mesh saves; tests compare the two).
    void recompute_blockers();

private:
    // The band-corrected diffuse transfer of n texels (grid indices `index`; null: texel k is k)
    // from their log-SH [16][n], into `out` [16][n], through the backend when there is one.
    void diffuse_transfer(const float* log_sh, std::size_t n, const std::uint32_t* index, float* out) const;
    // The blocked transfer of m texels (grid indices `index`) from their terrain-only and blocked
    // log-SH [16][m]: the log-SH path's, or with the exact terrain transfer `t_terrain` [16][m]
    // (no bounce) plus what the blockers change in the log-SH one.
    void blocked_transfer(const float* log_terrain, const float* log_blocked, std::size_t m, const std::uint32_t* index,
                          const float* t_terrain, float* out) const;
    bool exact_terrain() const { return options_.terrain_transfer == RendererOptions::TerrainTransfer::exact; }
    // Adds the bounced light's transfer to n texels' T [16][n] (grid indices `index`; null: texel k is k).
    void add_bounce(std::size_t n, const std::uint32_t* index, float* transfer) const;
    // Recomputes the blockers' part of the texels of `rect` (move_mesh).
    void update_blocked_rect(const visibility::TexelRect& rect);
    // Hands the sky bound the changed texels of a rectangle (grid indices, ascending) with their
    // blocked and terrain-only transfers [16][changed].
    void bound_changed(const visibility::TexelRect& rect, const std::vector<std::uint32_t>& changed,
                       const float* t_blocked, const float* t_terrain);
    // The weight the frame's diffuse pass gives texel t's sky term (blocker_sky_clamp.hpp).
    glm::vec3 sky_weight(std::size_t t) const;

    friend std::unique_ptr<ShadingState> compute_shading_state(const terrain::HeightGrid&, MaterialRaster, NormalField,
                                                               const RendererOptions&);

    const terrain::HeightGrid& grid_;
    RendererOptions options_;
    std::size_t texels_ = 0;
    MaterialRaster materials_;
    NormalField normals_;
    double visibility_s_ = 0, transfer_s_ = 0, bounce_s_ = 0;
    std::vector<float> bounce_;
    BounceSunGather bounce_sun_;
    std::string visibility_path_ = "cpu";
    std::vector<visibility::VisibilityStage> visibility_stages_;
    std::unique_ptr<DiffuseShading> diffuse_;
    std::vector<float> kept_transfer_;
    std::unique_ptr<ShadeField> diffuse_field_;
    std::vector<std::uint32_t> spec_index_;
    std::vector<float> spec_log_sh_, spec_terrain_log_sh_;
    std::vector<std::uint32_t> water_index_;
    std::vector<float> water_horizons_;
    blockers::SphereBlockers blockers_;
    // With blockers: the terrain's log-SH [16][texels] before the blockers were added.
    std::vector<float> terrain_log_sh_;
    // With blockers and the exact terrain transfer: the terrain-only T [16][texels] without the
    // bounce, what move_mesh starts from.
    std::vector<float> terrain_transfer_;
    std::unique_ptr<BlockerSkyClamp> sky_clamp_;
    std::unique_ptr<HorizonSkyLight> horizon_sky_;
    std::unique_ptr<visibility::SunShadowSweep> sun_sweep_;
    std::unique_ptr<visibility::BlockerSunShadow> blocker_sun_;
};

// The one-time step: visibility, diffuse transfer, what the views need. `grid` must outlive
// the state (its heights are swept for the sun every frame). Water texels get flat normals.
std::unique_ptr<ShadingState> compute_shading_state(const terrain::HeightGrid& grid, MaterialRaster materials,
                                                    NormalField normals, const RendererOptions& options = {});

// The direction towards the sun in ENU from user-facing angles.
glm::dvec3 sun_direction(const SunState& sun);

}  // namespace ts::render
