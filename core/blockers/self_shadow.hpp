#pragma once
// A mesh shadowed by its own bounding spheres (docs/blockers.md, "Mesh self-shadowing"): the
// spheres bound the surface, so every surface point lies inside at least one of them; a point
// ignores the spheres that contain it (their caps would cover its whole sphere of directions)
// and is shadowed by the others: their log-SH summed with ratio attenuation and the culling
// below its tangent plane (sphere_blocker.hpp), and the sun's disc covered analytically
// (sun_disc_occlusion.hpp).
#include <span>

#include <glm/vec3.hpp>

#include "core/blockers/sphere_blocker.hpp"
#include "core/blockers/sun_disc_occlusion.hpp"
#include "core/sh/sh_basis.hpp"

namespace ts::blockers {

// Whether `point` lies inside `sphere` (on its surface counts as inside: a surface point is
// where the bounding sphere touches the mesh).
bool sphere_contains(const Sphere& sphere, const glm::dvec3& point);

// Log-SH of what the spheres not containing `point` hide from it (normal: the surface's, for
// the culling and the hemisphere ratio). Zero when every sphere contains it.
sh::ShVec self_shadow_log_sh(std::span<const Sphere> spheres, const glm::dvec3& point, const glm::dvec3& normal,
                             double log_eps, const RatioAttenuation& options = {});

// Fraction of the sun's disc (unit direction `sun`) the spheres not containing `point` leave
// visible: prod (1 - covered_b) as the terrain's sun shadows combine them.
double self_shadow_sun(std::span<const Sphere> spheres, const glm::dvec3& point, const glm::dvec3& sun,
                       double sun_radius = kSunAngularRadiusRad);

}  // namespace ts::blockers
