#pragma once
// The reference the sphere blockers are measured against: the placed mesh's real triangles,
// ray-traced through a BVH (core/blockers/triangle_bvh.hpp), over the terrain's horizons.
// Slow by design (hundreds of rays per texel), for benches and accuracy tests only
// (docs/blockers.md, "Accuracy against the triangles").
//
// Sky visibility is the svf's definition (sky_integrals.hpp): the cosine-weighted share of the
// upper hemisphere about the zenith, (1/pi) int V cos(theta) d omega, where a direction is
// blocked below the terrain's horizon in its azimuth (linear between the D horizons) or by a
// triangle. Our log-SH result is put in the same terms by sky_visibility_of_log_sh.
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/blockers/triangle_bvh.hpp"
#include "core/mesh/placement.hpp"
#include "core/mesh/triangle_mesh.hpp"
#include "core/sh/exp_method.hpp"
#include "core/sh/sh_basis.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/visibility/blocker_footprint.hpp"
#include "core/visibility/horizon_set.hpp"

namespace ts::visibility {

// A mesh's triangles in the anchor frame of placed_spheres.hpp (placed as place_spheres places
// its spheres), with their BVH.
struct PlacedTriangles {
    glm::dvec2 anchor{0.0};
    blockers::TriangleBvh bvh;
};
PlacedTriangles place_triangles(const mesh::TriangleMesh& mesh, const mesh::Placement& placement, glm::dvec2 anchor,
                                double ground_height_m);

struct ReferenceOptions {
    int sky_strata = 24;   // sky directions: strata x strata, cosine-weighted about the zenith
    int sun_samples = 64;  // points on the sun's disc
    int threads = 0;
};

// Per texel of `rect` (row-major inside it): sky visibility with the terrain's horizons alone
// and with the triangles too. `horizons` covers the whole grid. curvature: 1 / (2 R_eff) or 0.
struct SkyReference {
    std::vector<float> terrain, with_mesh;
};
SkyReference reference_sky(const terrain::HeightGrid& grid, const HorizonSet& horizons, const PlacedTriangles& mesh,
                           const TexelRect& rect, double curvature, const ReferenceOptions& options);

// Per texel of `rect`: the fraction of the sun's disc (centre `sun`, unit ENU, angular radius
// sun_radius) the triangles leave visible.
std::vector<float> reference_sun(const terrain::HeightGrid& grid, const PlacedTriangles& mesh, const TexelRect& rect,
                                 const glm::dvec3& sun, double sun_radius, double curvature,
                                 const ReferenceOptions& options);

// On the mesh itself (its self-shadow, docs/blockers.md "Mesh self-shadowing"): from a point of
// its surface with unit normal `normal` (the side it faces), the cosine-weighted share of the
// hemisphere about the normal that misses every triangle (strata x strata stratified rays), and
// the share of the sun's disc that does (`sun_samples` rays). The rays start a hair off the
// surface (`offset` metres along the normal) so the point's own face does not hide it.
double reference_self_sky(const blockers::TriangleBvh& bvh, const glm::dvec3& point, const glm::dvec3& normal,
                          int strata, double offset);
double reference_self_sun(const blockers::TriangleBvh& bvh, const glm::dvec3& point, const glm::dvec3& normal,
                          const glm::dvec3& sun, double sun_radius, int sun_samples, double offset);

// The clamped cosine about the zenith, max(0, cos theta), projected onto the SH basis
// (numerically, so no convention of the rotation formulas is assumed).
sh::ShVec zenith_cosine_lobe();
// The same lobe about the unit direction n, from zenith_cosine_lobe() computed once by the
// caller (its zonal part turned to n).
sh::ShVec cosine_lobe_about(const sh::ShVec& zenith_lobe, const glm::dvec3& n);

// (1/pi) int exp(f) cos(theta) d omega over the upper hemisphere about the zenith, from 16
// log-SH coefficients f (one texel's, strided by `stride` floats as in log_sh rasters);
// lobe = zenith_cosine_lobe(), or cosine_lobe_about(n) for a surface of normal n.
double sky_visibility_of_log_sh(const float* f, std::size_t stride, sh::ExpMethod method, const sh::ShVec& lobe);

}  // namespace ts::visibility
