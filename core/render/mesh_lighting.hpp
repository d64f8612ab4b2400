#pragma once
// How a mesh standing over the terrain is lit, per vertex (docs/blockers.md, "Terrain -> mesh"
// and "Mesh self-shadowing"; the slides' steps 2 and 3 on the receiving side):
//
//   V_log(p)  = project(horizons of the terrain from p)       (PointHorizons, SliceProjector)
//             + sum over its own spheres not containing p      (self_shadow.hpp)
//   T_d(p, n) = exp(V_log + rot(F_diffuse, n)), band-corrected as the terrain's texels
//   per frame: sun_vis(p) = terrain's disc fraction in the sun's azimuth * own spheres' cover
//              L(p) = albedo (max(0, <T_d, L_sky>) + sun_vis max(0, n.s) E_sun / pi)
//
// so an aircraft low in a valley is darkened by the slopes, loses the sun behind a ridge and
// shadows itself, with the same sky SH and sun as the terrain. Every corner is lit twice, for
// its normal and the opposite one: a soup's faces are seen from either side (the view picks).
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/blockers/placed_spheres.hpp"
#include "core/light/sky.hpp"
#include "core/material/log_brdf.hpp"
#include "core/mesh/placement.hpp"
#include "core/mesh/triangle_mesh.hpp"
#include "core/sh/exp_method.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/visibility/horizon_sh.hpp"
#include "core/visibility/point_horizons.hpp"

namespace ts::render {

// A mesh's triangles in the frame of its spheres (placed_spheres.hpp: x east, y north of the
// anchor texel, z metres above the datum).
struct PlacedMesh {
    std::string name;
    glm::dvec2 anchor{0.0};
    std::vector<glm::dvec3> positions;  // 3 per triangle
    std::vector<glm::vec3> normals;     // 3 per triangle, unit, ENU
    std::vector<glm::vec3> albedo;      // 1 per triangle: the material's linear base colour
    std::size_t corners() const { return positions.size(); }
};

// Rotated, scaled and lifted exactly as place_spheres places the same mesh's spheres.
PlacedMesh place_mesh(const mesh::TriangleMesh& mesh, const mesh::Placement& placement, glm::dvec2 anchor,
                      double ground_height_m, std::string name = {});

// The texel-centre coordinates and the height above the datum of a point of an anchor frame.
glm::dvec3 anchor_frame_to_grid(const terrain::HeightGrid& grid, glm::dvec2 anchor, const glm::dvec3& p,
                                double curvature);

struct MeshLightingOptions {
    int directions = 32;   // terrain horizon azimuths from each vertex (as the texels' --directions)
    bool curvature = true;
    float terrain_log_eps = visibility::kDefaultVisibilityLogEps;  // as the texels' log-SH
    bool terrain_shadow = true;  // the terrain's horizons darken the mesh (off: open sky)
    bool self_shadow = true;     // the mesh's own spheres darken it
    double brdf_log_eps = sh::kDefaultBrdfLogEps;
    sh::ExpMethod exp_method = sh::ExpMethod::scaling_squaring;
    bool band_correction = true;
    int threads = 0;
};

class MeshLighting {
public:
    // `grid` and `spheres` (the same mesh's, placed at the same anchor; may be null: no
    // self-shadowing) must outlive this. `sphere_options` gives the spheres' log floor,
    // attenuation and the sun's radius.
    MeshLighting(const terrain::HeightGrid& grid, PlacedMesh mesh, const blockers::PlacedSpheres* spheres,
                 const blockers::SphereBlockerOptions& sphere_options, const MeshLightingOptions& options);

    const PlacedMesh& mesh() const { return mesh_; }
    // Lit receivers: corner k seen from its normal's side is k, from the other side corners() + k.
    std::size_t receivers() const { return 2 * mesh_.corners(); }
    // log-SH visibility [16][receivers()] and the diffuse transfer [16][receivers()].
    const std::vector<float>& log_visibility() const { return log_sh_; }
    const std::vector<float>& transfer() const { return transfer_; }
    double seconds() const { return seconds_; }
    std::size_t distinct_points() const { return points_.size(); }

    // Visible fraction of the sun's disc per receiver (unit ENU `sun`) into out[receivers()].
    void sun_visibility(const glm::dvec3& sun, std::vector<float>& out) const;
    // Radiance per receiver (linear RGB, the sky's units) into out[receivers()].
    void radiance(const light::SkySh& sky_sh, const light::SunDisc& sun, bool sun_up, std::vector<glm::vec3>& out) const;

private:
    const terrain::HeightGrid& grid_;
    PlacedMesh mesh_;
    const blockers::PlacedSpheres* spheres_;
    blockers::SphereBlockerOptions sphere_options_;
    MeshLightingOptions options_;
    visibility::PointHorizons horizons_;
    std::vector<glm::dvec3> points_;      // distinct corner positions, anchor frame
    std::vector<glm::dvec3> grid_points_; // the same as (col, row, height above datum)
    std::vector<std::uint32_t> point_of_; // corner -> distinct point
    std::vector<float> log_sh_, transfer_;
    double seconds_ = 0;
};

}  // namespace ts::render
