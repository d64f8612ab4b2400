#pragma once
// The share of the cosine-weighted sky a mesh's own spheres leave at a point of its surface
// with normal n, under a sky of even radiance: the spheres' caps (ts_sphere_sky_cover,
// sphere_occlusion_shared.h) combined as patches scattered independently over the hemisphere,
// 1 - prod (1 - C_b). Skipped or faded, as a surface point needs: a leaf holding the point (the
// point lies on the surface it bounds), a leaf whose centre is behind the tangent plane, and a
// leaf near the point, faded in over one radius off its surface (the spheres next to a point
// bound the surface it lies on; their caps, near a hemisphere just outside and nothing inside,
// would blotch it). Down the hierarchy a node whose cap is at most `detail` counts as its cover
// times its leaves' far share (projected_cover_share.hpp) and is not opened.
// It depends on the mesh alone, not on where it flies: the flythrough computes it once per
// vertex and side (gpu/fly/flythrough.cpp) for the aircraft's sky light.
#include <vector>

#include <glm/vec3.hpp>

#include "core/blockers/sphere_hierarchy.hpp"

namespace ts::blockers {

double self_sky_share(const std::vector<FlatSphereNode>& nodes, const std::vector<float>& far_share,
                      const glm::dvec3& point, const glm::dvec3& normal, double detail);

}  // namespace ts::blockers
