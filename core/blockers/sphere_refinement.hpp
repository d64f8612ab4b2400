#pragma once
// Shrinking a bounding sphere set while it keeps bounding the surface. Each sphere in turn
// (costliest first) is refitted to the surface cells that no other sphere holds; the refit
// holds them all, and the cells it lets go are held by others, so coverage never drops. A
// sphere left with nothing of its own is redundant: it is reused by splitting the costliest
// sphere's own cells in two (a sphere of radius 0 on input is such a free sphere).
#include <vector>

#include <glm/vec3.hpp>

#include "core/blockers/sphere_blocker.hpp"
#include "core/blockers/sphere_fit.hpp"
#include "core/blockers/surface_cover.hpp"

namespace ts::blockers {

// interiors: per sphere, the interior point its fits push towards. Spheres still free at the
// end (nothing left to split) are removed.
void refine_spheres(SurfaceCover& cover, std::vector<Sphere>& spheres, std::vector<glm::dvec3>& interiors,
                    const OutsideVolume& outside, int passes);

}  // namespace ts::blockers
