#pragma once
// The part of shading that depends on where the viewer is, for one view of a ShadingState:
//
//   specular transfer T_s = exp(V + rot(F_phong(alpha), r))   (texels with ks > 0)
//   water: mirror direction r, Fresnel F(n.v), V(r) from the horizons
//
// with v the direction towards the viewer (zenith for a map or any georeferenced extent, the
// camera for a perspective view) and r = 2 (n.v) n - v. One ViewShading serves every frame of
// its view and every target that looks from the same place (all map-like targets share one).
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "core/render/blocker_sky_clamp.hpp"
#include "core/render/shading_state.hpp"

namespace ts::render {

// Where the viewer is, per texel: one direction for all (a map: straight up) or one per texel.
struct ViewDirections {
    glm::vec3 uniform{0.0f, 0.0f, 1.0f};
    std::vector<glm::vec3> per_texel;  // empty = uniform
};

struct ViewShading {
    // Specular texels (the state's specular_index() order): transfer [16][n] and what the
    // per-frame sun term reads, together (the texels are scattered: one stream, not four gathers).
    struct SpecTexel {
        glm::vec3 normal, mirror;
        float ks, alpha;
    };
    std::vector<float> t_spec;
    std::vector<SpecTexel> spec;
    // With mesh blockers: the bound on the specular sky term <T_s, L> of the specular texels
    // they change (indices into the specular list, weight 1), as the diffuse one
    // (blocker_sky_clamp.hpp); empty without blockers.
    std::optional<BlockerSkyClamp> spec_clamp;
    // Water texels (the state's water_index() order).
    std::vector<glm::vec3> water_r;
    std::vector<float> water_fresnel, water_vis;
};

// The one-time step per view (a specular exponentiation over the state's specular texels).
ViewShading compute_view_shading(const ShadingState& state, const ViewDirections& view);

}  // namespace ts::render
