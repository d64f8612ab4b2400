#pragma once
// The solid (interior and surface cells) cut into `count` compact clusters by k-means
// (k-means++ seeds, Lloyd iterations) on the cell centres: each cluster is a blob of the
// solid, so the sphere bounding its surface pieces can sit inside it. Every surface cell then
// goes to its nearest cluster centre.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/blockers/voxel_solid.hpp"

namespace ts::blockers {

struct SolidClustering {
    std::vector<glm::dvec3> centers;   // count
    std::vector<int> surface_cluster;  // per entry of solid.surface_cells
};

struct ClusteringOptions {
    int count = 64;
    int max_points = 40000;  // solid cells beyond this are subsampled (evenly, seeded)
    int iterations = 12;
    std::uint64_t seed = 1;
    int threads = 0;
};

SolidClustering cluster_solid(const VoxelSolid& solid, const ClusteringOptions& options);

}  // namespace ts::blockers
