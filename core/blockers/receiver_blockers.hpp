#pragma once
// What one receiver point sees of a placed mesh's spheres (placed_spheres.hpp), through the
// sphere hierarchy: the spheres that count for its sky, and the part of the sun they leave.
// The receiver is in the mesh's anchor frame.
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/blockers/placed_spheres.hpp"
#include "core/blockers/sphere_log_sh_kernel.hpp"

namespace ts::blockers {

// Appends the mesh's spheres that count for the receiver's sky, with their centres relative
// to the receiver (so the receiver is the origin). The threshold (min_sine: a sphere counts
// when sin theta_b > min_sine, or the receiver is inside it) is applied down the hierarchy as a
// level of detail: a sphere above it always counts; a subtree below it is dropped when its
// sibling is above it; a node above it whose two children are both below it counts all its
// spheres, so a finer decomposition keeps the shadow of the pieces a coarser one keeps
// (docs/blockers.md). With options.cull_lower_hemisphere, spheres wholly below the plane of
// `normal` are dropped, whole subtrees at once.
void collect_sky_blockers(const PlacedSpheres& mesh, const glm::dvec3& receiver, const glm::dvec3& normal,
                          double min_sine, const RatioAttenuation& options, std::vector<Sphere>& out);
// The same into the accumulation kernel's lanes (sphere_log_sh_kernel.hpp).
void collect_sky_blockers(const PlacedSpheres& mesh, const glm::dvec3& receiver, const glm::dvec3& normal,
                          double min_sine, const RatioAttenuation& options, SphereLanes& out);

// Fraction of the sun's disc (unit direction `sun`) that the mesh's spheres leave visible from
// the receiver: the product over spheres of (1 - covered fraction). Exact for one sphere; where
// several partly cover the disc it takes their covers as independent, so overlapping
// penumbrae come out a little dark (umbrae are exact: any sphere covering all gives 0).
double sun_visible_past(const PlacedSpheres& mesh, const glm::dvec3& receiver, const glm::dvec3& sun,
                        double sun_radius);

// Fraction of the rays from the receiver along `disc` (unit directions over the sun's disc:
// sun_disc_directions) that miss the mesh's own triangles (mesh.model_triangles, not null).
double sun_visible_past_triangles(const PlacedSpheres& mesh, const glm::dvec3& receiver,
                                  std::span<const glm::dvec3> disc);

}  // namespace ts::blockers
