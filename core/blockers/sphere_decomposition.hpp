#pragma once
// A mesh as a set of spheres that bounds it: every point of its surface inside some sphere,
// with little volume outside the mesh's solid. Robust on real assets (open, self-intersecting
// polygon soups), no watertight mesh needed. The steps (docs/blockers.md):
//  1. voxel solid: surface cells with their clipped triangle pieces, interior by flood fill
//     after a one-cell closing (voxel_solid.hpp);
//  2. k-means of the solid cells into `count` clusters (solid_clustering.hpp);
//  3. per cluster, the sphere bounding its surface pieces, its centre pushed into the solid
//     (sphere_fit.hpp);
//  4. refinement: each sphere refitted to the cells only it holds, redundant spheres reused by
//     splitting the costliest (sphere_refinement.hpp).
// Bounding is exact by construction (spheres hold the corners of the clipped pieces, and a
// sphere is convex); surface_coverage measures it again on fresh surface samples.
#include <cstdint>
#include <vector>

#include "core/blockers/sphere_blocker.hpp"
#include "core/mesh/triangle_mesh.hpp"

namespace ts::blockers {

inline constexpr int kMinSpheres = 8;
inline constexpr int kMaxSpheres = 512;
// Bumped whenever the algorithm's output changes: part of the cache key (sphere_cache.hpp).
inline constexpr int kDecompositionVersion = 1;

struct DecompositionOptions {
    int count = 64;                // kMinSpheres .. kMaxSpheres
    int resolution = 128;          // voxel cells along the mesh's longest side
    int refine_passes = 2;
    int coverage_samples = 100000; // fresh surface samples for surface_coverage
    int volume_samples = 400000;   // Monte Carlo points for excess_volume_ratio
    std::uint64_t seed = 1;
    int threads = 0;               // 0 = one per core
};

struct SphereDecomposition {
    std::vector<Sphere> spheres;   // normalised model frame, metres
    double surface_coverage = 0.0;
    double excess_volume_ratio = 0.0;
    double seconds = 0.0;          // of the computation (a cache hit keeps the original figure)
    bool cached = false;
};

// Throws ts::InputError for a count outside [kMinSpheres, kMaxSpheres] or a resolution
// outside [16, 512].
void validate(const DecompositionOptions& options);

SphereDecomposition decompose_into_spheres(const mesh::TriangleMesh& mesh, const DecompositionOptions& options);

}  // namespace ts::blockers
