#pragma once
// Mesh blockers' sun shadows on the terrain, per frame: for every texel in a mesh's sun
// footprint (blocker_footprint.hpp), the fraction of the sun's disc the mesh leaves multiplies
// the terrain's sun visibility (sun_sweep.hpp or sun_visibility.hpp). Texels outside every
// footprint are not touched. The fraction (core/blockers/receiver_blockers.hpp) is the spheres'
// analytic cover of the disc, and where that is not the whole disc and the options' sun_caster
// is `triangles`, the share of sun_rays rays through the mesh's own triangles instead.
#include <vector>

#include "core/blockers/placed_spheres.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/visibility/blocker_footprint.hpp"

namespace ts::visibility {

struct SunShadowStats {
    long long texels_visited = 0;   // texels in the footprints this frame
    long long texels_shadowed = 0;  // texels whose visibility the spheres lowered
};

class BlockerSunShadow {
public:
    // The grid and the blockers must outlive it. curvature: 1 / (2 R_eff) or 0.
    BlockerSunShadow(const terrain::HeightGrid& grid, const blockers::SphereBlockers& blockers, double curvature,
                     int threads);

    // Multiplies `visibility` (grid texels, row-major; NaN voids kept) by the spheres' share of
    // the sun at (azimuth clockwise from north, elevation), degrees.
    SunShadowStats apply(double sun_azimuth_deg, double sun_elevation_deg, std::vector<float>& visibility) const;

    // The footprint rectangle of mesh k for this sun (tests, benches).
    TexelRect footprint(std::size_t mesh, double sun_azimuth_deg, double sun_elevation_deg) const;

private:
    const terrain::HeightGrid& grid_;
    const blockers::SphereBlockers& blockers_;
    double curvature_;
    int threads_;
    HeightRange range_;
    std::vector<double> max_drop_;  // per mesh: the largest curvature drop of any texel in its frame
};

}  // namespace ts::visibility
