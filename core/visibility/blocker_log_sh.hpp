#pragma once
// Mesh blockers joining the terrain's log-SH visibility (the method's step 3 -> 4): for every
// texel in a mesh's sky footprint (blocker_footprint.hpp), the log-SH of the spheres that
// subtend more than the threshold and reach above the texel's tangent plane, weighted by ratio
// attenuation over all meshes' kept spheres (core/blockers/sphere_blocker.hpp), is added to the
// texel's log-SH:
//   V_log(texel) = V_log^HF(texel) + sum_b w_b * rot(log-ZH(theta_b), dir_b).
// Called once, from the visibility seam (complete_on_cpu), so every consumer gets it.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/blockers/placed_spheres.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/visibility/horizon_set.hpp"

namespace ts::visibility {

struct BlockerStageStats {
    long long texels_visited = 0;  // texels in the footprints
    long long texels_changed = 0;  // texels that got at least one sphere
    long long sphere_texel_pairs = 0;  // leaf spheres accumulated, summed over texels
};

// log_sh: [16][window texels] as VisibilityResult::log_sh, for the receivers of `window`
// (resolved: no -1 sizes), the caps' floor blockers.options.log_eps. Void texels (NaN) are left
// as they are. curvature: 1 / (2 R_eff) or 0.
BlockerStageStats add_blocker_log_sh(const terrain::HeightGrid& grid, const ReceiverWindow& window,
                                     const blockers::SphereBlockers& blockers, double curvature,
                                     int threads, float* log_sh);

// For a device that accumulates the spheres itself (gpu/visibility's blocker_log_sh.comp: every
// sphere at every receiver, the accumulation kernel's formulas): the receivers add_blocker_log_sh
// would visit without culling, for any number of meshes. Applies with sky_culling = none.
bool device_can_add_blockers(const blockers::SphereBlockers& blockers);

struct FlatBlockerReceivers {
    std::vector<std::size_t> texels;      // per receiver: window-relative index (row * width + col)
    // Per entry: a receiver and one mesh whose bounding sphere passes the threshold there, the
    // entries of a receiver consecutive (with one mesh: one entry per receiver, in order). The
    // device sums a receiver's entries and attenuates them together, as add_blocker_log_sh does.
    std::vector<std::uint32_t> receiver;  // index into texels
    std::vector<std::uint32_t> mesh;      // index into blockers.meshes
    std::vector<glm::vec3> positions;     // in that mesh's anchor frame, as its spheres
    std::vector<glm::vec3> normals;       // unit, as add_blocker_log_sh takes them
    long long texels_visited = 0;         // texels in any footprint (BlockerStageStats)
};
// Every non-void texel of the window's part of the meshes' sky footprints where some mesh's
// bounding sphere passes the threshold. Requires device_can_add_blockers.
FlatBlockerReceivers flat_blocker_receivers(const terrain::HeightGrid& grid, const ReceiverWindow& window,
                                            const blockers::SphereBlockers& blockers, double curvature, int threads);

}  // namespace ts::visibility
