#pragma once
// Adaptive quality for the mesh blockers (render, relight --max-error E with --mesh): how many
// spheres a mesh needs for its share of the picture's relative radiance error.
//
// Against the mesh's triangles the spheres err in two ways (docs/blockers.md, "Accuracy against
// the triangles"): the sun shadow is the spheres' outline, larger than the triangles' (the
// spheres bound the mesh), and that error shrinks as spheres are added; the sky shadow's error
// stays near 0.005 of sky visibility over its footprint whatever the count. Both are confined to
// footprints, so over a picture of area A their RMS is that of the footprint times
// sqrt(footprint / A): a mesh far smaller than the picture needs few spheres, a close-up many.
//
//   sun   margin x (sqrt(M) + sqrt(a)) / sqrt(A) x sin(e) / mean(max(0, n.s))
//   sky   kSkyFootprintRmse x sqrt(F / A)
//
// M is the area where exactly one of the triangles' and the spheres' shadows falls on flat
// ground (flat_shadow_outline), a the area of a texel: the renderer samples the shadows at
// texel centres, so a sliver of mismatch can flip a whole texel, and (sqrt(M) + sqrt(a))^2 =
// M + 2 sqrt(M a) + a bounds the texels' share with room for that. The last factor bounds the
// direct sun of a lit texel over the picture's mean radiance (the mean without the sky and the
// cast shadows: larger ratios only). F is the area of the sky footprint (the ground where the
// spheres' caps pass the solid-angle threshold).
// Errors of parts add at most linearly (the RMS is a norm), so the picture's bound is the
// terrain's prediction plus every mesh's.
#include <functional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/blockers/sphere_blocker.hpp"
#include "core/mesh/placement.hpp"
#include "core/mesh/triangle_mesh.hpp"

namespace ts::quality {

// The spheres' sky-visibility error against the triangles, RMS over their sky footprint, over
// the picture's mean sky visibility: the largest tests/stability/blocker_max_error_test.cpp
// measures on its fitted Grenoble cases (0.0111, counting the triangles' faint darkening beyond
// the footprint) times 1.25.
inline constexpr double kSkyFootprintRmse = 0.014;
// Margin on the sun term for terrain that is not flat and for the texel sampling of the outline.
inline constexpr double kSunOutlineMargin = 1.5;

// The sphere counts tried, cheapest first.
const std::vector<int>& candidate_sphere_counts();

// The sun shadows of a mesh's triangles and of its spheres on flat ground (parallel projection
// along `sun`, unit ENU, pointing to the sun), rasterised at `cells` across the silhouette's larger
// side. Areas in square metres on the ground (the silhouette's over sun.z). Zero when the sun is
// not above the horizon.
struct ShadowOutline {
    double triangle_area_m2 = 0, sphere_area_m2 = 0;
    double mismatch_area_m2 = 0;  // under exactly one of the two
};
ShadowOutline flat_shadow_outline(const mesh::TriangleMesh& mesh, std::span<const blockers::Sphere> model_spheres,
                                  const mesh::Placement& placement, const glm::dvec3& sun, int cells = 512);

// One sun of the pictures and what the terrain does to its light.
struct BlockerSun {
    glm::dvec3 direction{0, 0, 1};  // unit ENU, to the sun
    double mean_lit_cosine = 1;     // mean over the picture's texels of max(0, n.s)
};

struct MeshErrorTerms {
    double sun = 0, sky = 0;
    double total() const { return sun + sky; }
};

// The ground a picture covers and how finely.
struct PictureArea {
    double area_m2 = 0;        // of its valid texels
    double texel_area_m2 = 0;  // of one texel under the mesh
};

// The predicted error one mesh with these spheres adds to the picture, the worst over `suns`
// for the sun term; sky_footprint_area_m2 is the ground where its spheres shade the sky
// (visibility::sky_footprint). sun_by_triangles: the mesh's triangles cast its sun shadow
// (SphereBlockerOptions::sun_caster), so M = 0 and the sun term is the texels' sampling alone,
// whatever the count.
MeshErrorTerms predicted_mesh_error(const mesh::TriangleMesh& mesh, std::span<const blockers::Sphere> model_spheres,
                                    const mesh::Placement& placement, std::span<const BlockerSun> suns,
                                    const PictureArea& picture, double sky_footprint_area_m2, bool sun_by_triangles);

struct SphereCountChoice {
    int spheres = 0;
    double predicted_error = 0;  // of every mesh together
    bool met = true;             // false: no count is predicted under the budget
};

// The fewest spheres (one count for every mesh) whose predicted error, `error_of(count)`, is at
// most `budget`; when none is (met = false), the count of the least predicted error, the fewest
// of equals (with the triangles casting the sun the error hardly depends on the count, and more
// spheres would cost without helping). error_of is called in rising count and not past the choice.
SphereCountChoice choose_sphere_count(double budget, const std::function<double(int)>& error_of);

}  // namespace ts::quality
