#pragma once
// Sphere blockers placed over a height grid: each mesh's spheres in a metric frame anchored at a
// point of the grid, and the knobs of casting them onto the terrain (docs/blockers.md).
//
// The frame is the one the terrain code measures in (core/visibility: horizons, sun sweep,
// perspective view): x east along the grid's rows, y north against them, metres from the
// anchor's texel-centre coordinates with each row's spacing (HeightGrid::dx_m / dy_m), z metres
// above the DEM's datum (the grid's heights), the terrain dropped by Earth curvature with
// distance from the anchor. A receiver texel (c, r) of height z sits at
//   ((c - anchor.x) dx(r), (anchor.y - r) dy(r), z - curvature * horizontal distance^2).
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>

#include "core/blockers/sphere_blocker.hpp"
#include "core/blockers/sphere_hierarchy.hpp"
#include "core/blockers/sun_disc_occlusion.hpp"
#include "core/blockers/triangle_bvh.hpp"
#include "core/mesh/placement.hpp"
#include "core/mesh/triangle_mesh.hpp"

namespace ts::blockers {

struct SphereBlockerOptions {
    // Sphere solid-angle threshold (steradians): a mesh darkens a texel's sky only while its
    // bounding sphere subtends more than this there, which bounds the sky footprint to a disc of
    // radius r / sin(theta_min) around it. With sky_culling = hierarchy it is also applied down
    // the sphere hierarchy as a level of detail (receiver_blockers.hpp): a sphere, or the finest
    // hierarchy node whose spheres are each below it, counts while it subtends more than this;
    // 0.01 sr hides at most 0.01 / pi = 0.3% of a texel's cosine-weighted sky per dropped part.
    double min_solid_angle_sr = 0.01;
    // How a texel of the sky footprint picks the spheres it sums: `hierarchy` walks the sphere
    // hierarchy with the threshold above as a level of detail, dropping small parts beside large
    // ones and whole subtrees below the tangent plane (receiver_blockers.hpp); `none` keeps every
    // sphere of every mesh whose bounding sphere passes the threshold there (the tangent-plane
    // cull of `attenuation` still applies per sphere, inside the accumulation kernel).
    // Measured in docs/blockers.md ("A moving aircraft, throughput").
    enum class SkyCulling { hierarchy, none };
    SkyCulling sky_culling = SkyCulling::none;
    RatioAttenuation attenuation;  // culling below the tangent plane and the solid-angle ratio
    // Log-visibility inside a sphere's cap. Not the terrain's floor (log 0.1): an order-4 SH
    // cap is smeared wide and shallow, where exp(f) ~ 1 + f, so a floor L darkens a small cap
    // like an occluder of opacity -L; log 0.1 = -2.3 made the sky under a sphere up to 0.21
    // too dark against the opaque cap, -1 keeps small caps right (docs/blockers.md).
    double log_eps = -1.0;
    double sun_radius_rad = kSunAngularRadiusRad;
    // What casts a mesh's sun shadow on the terrain. `triangles`: rays from each texel the
    // spheres shadow to sun_rays points of the sun's disc, through the mesh's own triangles
    // (PlacedSpheres::model_triangles), so the shadow has the aircraft's outline and the disc's
    // penumbra; the spheres bound the mesh, so a texel they leave in full sun is in full sun.
    // `spheres`: the spheres' analytic cover of the disc, whose outline is the union's (larger
    // than a thin wing's by its chord over sin(elevation)). A mesh placed without triangles
    // falls back to its spheres. Measured in docs/blockers.md ("The sun shadow's caster").
    enum class SunCaster { triangles, spheres };
    SunCaster sun_caster = SunCaster::triangles;
    int sun_rays = 16;
};

// One mesh's spheres in its anchor frame (above), with their hierarchy for culling.
struct PlacedSpheres {
    std::string name;                // for messages (the mesh file)
    glm::dvec2 anchor{0.0};          // texel-centre coordinates (col, row) of the frame's origin
    std::vector<Sphere> spheres;     // x east, y north of the anchor, z above the datum, metres
    SphereHierarchy hierarchy;       // over `spheres`; nodes[0].bound holds them all
    // The mesh's own triangles in the normalised model frame (shared by every placement of it),
    // for the sun shadow they cast (SphereBlockerOptions::sun_caster); null: the spheres cast it.
    std::shared_ptr<const TriangleBvh> model_triangles;
    // This frame -> the model frame: model = frame_to_model * (p - model_origin).
    glm::dmat3 frame_to_model{1.0};
    glm::dvec3 model_origin{0.0};
};

struct SphereBlockers {
    std::vector<PlacedSpheres> meshes;
    SphereBlockerOptions options;
    bool empty() const { return meshes.empty(); }
    std::size_t sphere_count() const;
};

// The spheres of a mesh decomposition (normalised model frame) placed by `placement` at the
// anchor: rotated and scaled as mesh::model_to_enu, lifted to placement.height_m (plus
// ground_height_m when above_ground). Throws ts::InputError for a bad placement.
PlacedSpheres place_spheres(std::span<const Sphere> model_spheres, const mesh::Placement& placement,
                            glm::dvec2 anchor, double ground_height_m, std::string name = {});

// The BVH of a mesh's triangles in its normalised model frame, for PlacedSpheres::model_triangles.
std::shared_ptr<const TriangleBvh> model_triangle_bvh(const mesh::TriangleMesh& mesh);

// Sphere solid-angle threshold as the sine of the cap half-angle it corresponds to:
// 2 pi (1 - cos theta_min) = min_solid_angle_sr.
double min_cap_sine(double min_solid_angle_sr);

}  // namespace ts::blockers
