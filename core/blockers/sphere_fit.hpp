#pragma once
// One sphere bounding a set of points (the surface pieces a sphere answers for) with as little
// volume outside the mesh solid as a short search finds [after Wang et al. 2006, whose
// variational sphere sets minimise exactly that outside volume]. The minimal enclosing sphere
// of a patch of surface has its centre on the patch, so half of it sticks out; moving the
// centre into the solid (towards an interior point of the cluster) and growing the radius to
// keep every point usually leaves much less outside. Whatever the centre, the radius is the
// largest distance to a point: the result always bounds the points.
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/blockers/sphere_blocker.hpp"
#include "core/blockers/voxel_solid.hpp"

namespace ts::blockers {

// The volume of a sphere outside the solid, estimated from a fixed set of points in the unit
// ball (the same for every sphere, so comparisons between candidate spheres are smooth).
class OutsideVolume {
public:
    explicit OutsideVolume(const VoxelSolid& solid, int samples = 512);
    double operator()(const Sphere& s) const;

private:
    const VoxelSolid& solid_;
    std::vector<glm::dvec3> unit_ball_;
};

// What a fit minimises: the outside volume, plus a small part of the whole volume so that of
// two spheres equally outside the smaller wins (fewer overlaps, tighter culling).
double fit_cost(const Sphere& s, const OutsideVolume& outside);

// interior: a point of the solid near the points (the cluster's centre), where the search
// starts pushing the centre.
Sphere fit_bounding_sphere(std::span<const glm::dvec3> points, const glm::dvec3& interior, const OutsideVolume& outside);

}  // namespace ts::blockers
