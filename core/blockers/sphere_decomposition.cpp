#include "core/blockers/sphere_decomposition.hpp"

#include <string>

#include "core/blockers/solid_clustering.hpp"
#include "core/blockers/sphere_fit.hpp"
#include "core/blockers/sphere_refinement.hpp"
#include "core/blockers/sphere_set_metrics.hpp"
#include "core/blockers/surface_cover.hpp"
#include "core/blockers/voxel_solid.hpp"
#include "core/mesh/surface_sampling.hpp"
#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::blockers {

void validate(const DecompositionOptions& o) {
    if (o.count < kMinSpheres || o.count > kMaxSpheres)
        throw QuantityError(Quantity::sphere_count, "", "must be in " + std::to_string(kMinSpheres) + ".." +
                                                          std::to_string(kMaxSpheres) + " (got " + std::to_string(o.count) + ")");
    if (o.resolution < 16 || o.resolution > 512)
        throw QuantityError(Quantity::sphere_resolution, "", "must be in 16..512 (got " + std::to_string(o.resolution) + ")");
    if (o.refine_passes < 0 || o.coverage_samples < 0 || o.volume_samples < 0)
        throw InputError("sphere decomposition: negative pass or sample count");
}

SphereDecomposition decompose_into_spheres(const mesh::TriangleMesh& mesh, const DecompositionOptions& o) {
    validate(o);
    const Stopwatch clock;
    const VoxelSolid solid = voxelize_solid(mesh, o.resolution, o.threads);

    ClusteringOptions co;
    co.count = o.count;
    co.seed = o.seed;
    co.threads = o.threads;
    const SolidClustering clusters = cluster_solid(solid, co);
    std::vector<std::vector<int>> members(std::size_t(o.count));
    for (int e = 0; e < int(clusters.surface_cluster.size()); ++e)
        members[std::size_t(clusters.surface_cluster[std::size_t(e)])].push_back(e);

    SurfaceCover cover(solid);
    const OutsideVolume outside(solid);
    std::vector<Sphere> spheres(std::size_t(o.count), Sphere{glm::dvec3(0.0), 0.0});  // radius 0: free
    std::vector<glm::dvec3> interiors = clusters.centers;
    parallel_for(o.count, thread_count(o.threads), [&](int c, int) {
        if (members[std::size_t(c)].empty()) return;
        spheres[std::size_t(c)] =
            fit_bounding_sphere(cover.corners_of(members[std::size_t(c)]), interiors[std::size_t(c)], outside);
    });
    refine_spheres(cover, spheres, interiors, outside, o.refine_passes);

    SphereDecomposition out;
    out.spheres = std::move(spheres);
    // Fresh samples: a seed the construction never used.
    const auto samples = mesh::sample_surface(mesh, o.coverage_samples, o.seed ^ 0x9e3779b97f4a7c15ull);
    out.surface_coverage = surface_coverage(out.spheres, samples, o.threads);
    out.excess_volume_ratio = excess_volume_ratio(out.spheres, solid, o.volume_samples, o.seed + 17, o.threads);
    out.seconds = clock.seconds();
    return out;
}

}  // namespace ts::blockers
