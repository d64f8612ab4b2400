#pragma once
// For each node of a flattened sphere hierarchy, the share of its bound's disc that the discs of
// the leaves below it cover, seen along the model's z axis (the spheres projected onto the xy
// plane; a leaf: 1). Far from a node (distance >> its radius) the cosine-weighted sky its leaves
// hide is its bound's cover times this share, seen from below or above: what the flythrough's
// sky shadow takes for a node whose cap is small from a receiver on the terrain under the
// aircraft. Sphere decompositions overlap heavily, so this is well under the share the leaves
// would keep scattered independently over the bound (1 - prod (1 - (r_b / r)^2)).
#include <vector>

#include "core/blockers/sphere_hierarchy.hpp"

namespace ts::blockers {

// `samples` points across the bound's diameter (a grid over its disc).
std::vector<float> projected_cover_share(const std::vector<FlatSphereNode>& nodes, int samples = 48);

}  // namespace ts::blockers
