#pragma once
// The sun's part of a map frame's per-texel radiance: albedo/pi E_sun max(0, n.s) times the
// terrain's visible fraction of the sun's disc (FrameRenderer's diffuse sun term; the few
// specular and water texels keep their sun terms in the rest), never more than the texel's
// radiance. What a blocker's sun shadow takes away from a texel (the flythrough's aircraft).
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/light/sky.hpp"
#include "core/render/render_scene.hpp"

namespace ts::render {

// `radiance`: the frame the scene rendered last for `sun` under `sky` (its grid's texels).
void diffuse_sun_part(const Scene& scene, const SunState& sun, const light::Sky& sky,
                      std::span<const glm::vec3> radiance, std::vector<glm::vec3>& out);

}  // namespace ts::render
