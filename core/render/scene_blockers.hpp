#pragma once
// Meshes standing over a DEM, turned into the sphere blockers the visibility and the sun
// shadows read (core/blockers/placed_spheres.hpp): each placement's lon/lat becomes the anchor
// of its frame on the grid, an `agl` height is added to the terrain's height there.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/blockers/placed_spheres.hpp"
#include "core/geo/georef.hpp"
#include "core/mesh/placement.hpp"
#include "core/mesh/triangle_mesh.hpp"
#include "core/terrain/height_grid.hpp"

namespace ts::render {

// One mesh of a scene: its bounding spheres in the normalised model frame (a decomposition)
// and where it stands.
struct SceneMesh {
    std::string name;  // the mesh file, for messages
    mesh::Placement placement;
    std::vector<blockers::Sphere> model_spheres;
    // Its triangles and materials (normalised model frame), for drawing it in perspective views
    // lit per vertex (mesh_lighting.hpp) and for the sun shadow they cast (SphereBlockerOptions::
    // sun_caster); null: only its spheres' shadows.
    std::shared_ptr<const mesh::TriangleMesh> triangles;
};

// Texel-centre coordinates (col, row) of the placement's lon/lat. Throws ts::InputError naming
// the mesh when it lies off the DEM (outside its outer edges) or the placement is invalid.
glm::dvec2 mesh_anchor(const geo::Georef& georef, const mesh::Placement& placement, const std::string& name);
// The placement with its heading (from true north) turned onto the grid at `anchor` (texel
// centres): a projected grid's north is not true north (Georef::grid_azimuth_of_north_deg).
mesh::Placement placement_on_grid(const geo::Georef& georef, const mesh::Placement& placement, glm::dvec2 anchor);

// The terrain's height at texel-centre coordinates (bilinear over valid texels; NaN if void).
double ground_height(const terrain::HeightGrid& grid, glm::dvec2 texel);

// Places every mesh. `warnings` gets one line per mesh whose spheres all lie below the
// terrain under its anchor (it then shadows nothing but the texels inside it).
blockers::SphereBlockers place_scene_meshes(std::span<const SceneMesh> meshes, const terrain::HeightGrid& grid,
                                            const geo::Georef& georef, const blockers::SphereBlockerOptions& options,
                                            std::vector<std::string>& warnings);

}  // namespace ts::render
