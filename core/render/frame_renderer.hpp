#pragma once
// One frame of per-texel radiance under a sun and sky, from the view-independent state and one
// view's shading (relighting is cheap because neither changes with the light):
//
// per frame: sky SH L (the diffuse fit for T_d, project_diffuse_sky_sh; the projection for T_s,
// project_sky_sh), sky table (water), sun visibility (the state's sweep),
// then per texel
//   L_out = albedo (E_h / pi + <T_d - T_h, L>) + ks <T_s, L>
//         + sun_vis E_sun [albedo/pi max(0, n.s) + ks (alpha+1)/(2 pi) max(0, r.s)^alpha [n.s > 0]]
//   water: F L_sky(r) V(r) + (1 - F) 0.02 <T_d, L> + sun glint F L_sun [r in the disc] + (1 - F) 0.02/pi E_sun n.s
// (E_h / pi the sky's light over the texel's horizons and T_h its own exact transfer, with
// `--sky-light horizons`, else 0: horizon_sky_light.hpp; <T_d, L> of texels mesh blockers
// change: at most the terrain's alone, blocker_sky_clamp.hpp;
// T_d: shading_state.hpp; T_s, r, F, V(r): view_shading.hpp; the BRDFs: docs/rendering.md).
//
//   auto state = compute_shading_state(grid, materials, normals, options);   // once
//   ViewShading view = compute_view_shading(*state, {});                     // once per view
//   FrameRenderer frame(*state, view);
//   frame.render(sky, sun, radiance);                                        // per frame
#include <array>
#include <cstddef>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/light/sky.hpp"
#include "core/light/sky_sh.hpp"
#include "core/render/shading_state.hpp"
#include "core/light/sky_table.hpp"
#include "core/render/view_shading.hpp"

namespace ts::render {

struct FrameTimings {
    double sky_s = 0, sun_visibility_s = 0, shading_s = 0;
};

class FrameRenderer {
public:
    // `state` and `view` must outlive the renderer; the state's sun sweep is used every frame.
    FrameRenderer(ShadingState& state, const ViewShading& view);

    std::size_t texels() const { return state_.texels(); }
    int width() const { return state_.width(); }
    int height() const { return state_.height(); }
    const ShadingState& state() const { return state_; }

    // Radiance of every texel (linear RGB, the sky's units) into `out` (resized once to texels()).
    // `sky` is the sky of this frame (its sun disc gives the sun's irradiance and direction).
    void render(const light::Sky& sky, const SunState& sun, std::vector<glm::vec3>& out);
    // The same with the sky's SH already made: `sky_sh` for the terrain's diffuse term
    // (project_diffuse_sky_sh), `radiance_sh` for the specular texels (project_sky_sh; read only
    // when there are some).
    void render(const light::Sky& sky, const light::SkySh& sky_sh, const light::SkySh& radiance_sh,
                const SunState& sun, std::vector<glm::vec3>& out);

    // The sun's visible fraction per texel of the last frame (0 when the sun was down).
    const std::vector<float>& sun_visibility() const { return sun_vis_; }
    // The same from the grid's own terrain alone (what the meshes' and outer shadows left out).
    const std::vector<float>& terrain_sun_visibility() const {
        return state_.has_other_sun_shadows() ? terrain_sun_vis_ : sun_vis_;
    }
    // With RendererOptions::keep_sun_horizon, each texel's horizon in the sun's azimuth less the
    // sun's elevation (radians; ShadingState::sun_visibility), else empty.
    const std::vector<float>& sun_horizon() const { return sun_horizon_; }
    const FrameTimings& last_timings() const { return timings_; }

private:
    ShadingState& state_;
    const ViewShading& view_;
    light::DiffuseSkyProjector diffuse_sky_;  // the sky's SH for <T_d, L>, its fit kept per rule
    // Per-frame scratch, allocated once.
    std::vector<glm::vec3> diffuse_rgb_, spec_rgb_;  // diffuse_rgb_: backend path only
    std::vector<glm::vec3> sky_add_;  // the sky light over the horizons and the gathered bounce's sun, E / pi
    // The bounce's sun part gathered per frame, and the gather's scratch (each texel's sun in it).
    std::vector<float> bounce_sun_;
    BounceSunGather::Scratch bounce_scratch_;
    // Gathers it and adds it, times E_sun / pi, to sky_add_.
    void add_gathered_bounce_sun(const glm::vec3& sun_dir, const glm::vec3& e_diffuse, int threads);
    std::vector<float> sun_vis_, terrain_sun_vis_;  // terrain_sun_vis_: only with other sun shadows
    std::vector<float> sun_horizon_;
    light::SkyTable sky_table_{light::SkyGrid::whole_sphere(128, 64)};
    FrameTimings timings_;
};

}  // namespace ts::render
