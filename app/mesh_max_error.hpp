#pragma once
// --max-error with --mesh (render, relight): the meshes' predicted error against their
// triangles (core/quality/blocker_quality.hpp) for every candidate sphere count, over this
// DEM and these suns, computed on demand and kept, so the terrain's setting and the sphere count
// are chosen together (quality::choose_radiance's rest_fits).
#include <map>

#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "app/mesh_options.hpp"
#include "core/blockers/sphere_decomposition.hpp"
#include "core/quality/blocker_quality.hpp"
#include "core/render/shading_state.hpp"
#include "core/terrain/height_grid.hpp"

namespace ts::app {

class MeshErrorModel {
public:
    MeshErrorModel(const dem::Dem& dem, const terrain::HeightGrid& grid, const std::vector<render::SceneMesh>& meshes,
                   const std::vector<render::SunState>& suns, const MeshArgs& args);

    // Every mesh's predicted error together with `count` spheres each (decomposed or from the
    // cache on first use).
    double error(int count);
    quality::MeshErrorTerms terms(int count);
    // Mesh k's spheres at `count` (after error(count)).
    const blockers::SphereDecomposition& spheres(std::size_t mesh, int count) const;
    double picture_area_m2() const { return picture_area_m2_; }

private:
    const terrain::HeightGrid& grid_;
    const std::vector<render::SceneMesh>& meshes_;
    const MeshArgs& args_;
    std::vector<quality::BlockerSun> suns_;
    std::vector<glm::dvec2> anchors_;  // per mesh: texel-centre coordinates of its placement
    std::vector<double> grounds_;      // per mesh: the terrain's height there (0 over a void)
    double picture_area_m2_ = 0;
    std::map<int, quality::MeshErrorTerms> terms_;
    std::map<std::pair<std::size_t, int>, blockers::SphereDecomposition> spheres_;
};

// The line --max-error prints for the meshes' choice.
std::string mesh_choice_line(const quality::SphereCountChoice& choice, const quality::MeshErrorTerms& terms,
                             double picture_area_m2, std::size_t meshes, double budget);

}  // namespace ts::app
