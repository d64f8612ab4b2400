#pragma once
// How well a sphere set stands for a mesh: the fraction of surface points it holds, and the
// volume it adds outside the mesh's solid.
#include <cstdint>
#include <span>

#include <glm/vec3.hpp>

#include "core/blockers/sphere_blocker.hpp"
#include "core/blockers/voxel_solid.hpp"

namespace ts::blockers {

// Fraction of `points` inside at least one sphere.
double surface_coverage(std::span<const Sphere> spheres, std::span<const glm::dvec3> points, int threads);

// Monte Carlo: (volume of the union of the spheres outside the voxel solid) / (solid volume),
// from `samples` uniform points in the union's box.
double excess_volume_ratio(std::span<const Sphere> spheres, const VoxelSolid& solid, int samples,
                           std::uint64_t seed, int threads);

}  // namespace ts::blockers
