#include "app/mesh_max_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/blockers/placed_spheres.hpp"
#include "core/blockers/sphere_cache.hpp"
#include "core/geo/azimuth.hpp"
#include "core/render/scene_blockers.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/util/angles.hpp"
#include "core/visibility/blocker_footprint.hpp"

namespace ts::app {
namespace {

// At most this many suns of a series are modelled, evenly spread (the outline changes slowly
// with the sun).
constexpr std::size_t kMaxModelledSuns = 24;

}  // namespace

MeshErrorModel::MeshErrorModel(const dem::Dem& dem, const terrain::HeightGrid& grid,
                               const std::vector<render::SceneMesh>& meshes, const std::vector<render::SunState>& suns,
                               const MeshArgs& args)
    : grid_(grid), meshes_(meshes), args_(args) {
    const render::NormalField n = render::terrain_normals(grid);
    std::vector<std::size_t> valid;
    for (int r = 0; r < grid.height; ++r)
        for (int c = 0; c < grid.width; ++c) {
            const std::size_t k = std::size_t(r) * std::size_t(grid.width) + std::size_t(c);
            if (std::isnan(grid.z[k])) continue;
            valid.push_back(k);
            picture_area_m2_ += grid.dx_m[std::size_t(r)] * grid.dy_m[std::size_t(r)];
        }
    const std::size_t step = std::max<std::size_t>(1, (suns.size() + kMaxModelledSuns - 1) / kMaxModelledSuns);
    for (std::size_t i = 0; i < suns.size(); i += step) {
        quality::BlockerSun s;
        s.direction =
            geo::enu_direction(geo::azimuth_cw_from_north_to_phi(suns[i].azimuth_deg), radians(suns[i].elevation_deg));
        double sum = 0;
        for (std::size_t k : valid) sum += std::max(0.0, n.x[k] * s.direction.x + n.y[k] * s.direction.y + n.z[k] * s.direction.z);
        s.mean_lit_cosine = valid.empty() ? 0.0 : sum / double(valid.size());
        suns_.push_back(s);
    }
    for (const render::SceneMesh& mesh : meshes) {
        anchors_.push_back(render::mesh_anchor(dem.georef, mesh.placement, mesh.name));
        const double ground = render::ground_height(grid, anchors_.back());
        grounds_.push_back(std::isnan(ground) ? 0.0 : ground);
    }
}

quality::MeshErrorTerms MeshErrorModel::terms(int count) {
    if (auto it = terms_.find(count); it != terms_.end()) return it->second;
    const std::filesystem::path cache =
        args_.cache_dir.empty() ? blockers::default_sphere_cache_dir() : std::filesystem::path(args_.cache_dir);
    const blockers::SphereBlockerOptions options = blocker_options(args_);
    const double min_sine = blockers::min_cap_sine(options.min_solid_angle_sr);
    const bool sun_by_triangles = options.sun_caster == blockers::SphereBlockerOptions::SunCaster::triangles;
    quality::MeshErrorTerms sum;
    for (std::size_t m = 0; m < meshes_.size(); ++m) {
        const render::SceneMesh& mesh = meshes_[m];
        blockers::DecompositionOptions d;
        d.count = count;
        const blockers::SphereDecomposition& sd =
            spheres_.emplace(std::pair{m, count}, blockers::decompose_cached(*mesh.triangles, d, cache)).first->second;
        const glm::dvec2 anchor = anchors_[m];
        const blockers::PlacedSpheres placed = blockers::place_spheres(sd.spheres, mesh.placement, anchor, grounds_[m], mesh.name);
        const visibility::TexelRect rect = visibility::sky_footprint(grid_, placed, min_sine);
        const std::size_t row = std::size_t(std::clamp(int(std::lround(anchor.y)), 0, grid_.height - 1));
        const double texel_m2 = grid_.dx_m[row] * grid_.dy_m[row];
        const quality::MeshErrorTerms e = quality::predicted_mesh_error(
            *mesh.triangles, sd.spheres, mesh.placement, suns_, {picture_area_m2_, texel_m2}, double(rect.texels()) * texel_m2,
            sun_by_triangles);
        sum.sun += e.sun, sum.sky += e.sky;
    }
    terms_[count] = sum;
    return sum;
}

double MeshErrorModel::error(int count) { return terms(count).total(); }

const blockers::SphereDecomposition& MeshErrorModel::spheres(std::size_t mesh, int count) const {
    return spheres_.at({mesh, count});
}

std::string mesh_choice_line(const quality::SphereCountChoice& c, const quality::MeshErrorTerms& t,
                             double picture_area_m2, std::size_t meshes, double budget) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "--max-error: %d spheres for %s (predicted %.3g of relative radiance error: sun shadow %.3g + sky "
                  "%.3g over a %.3g km2 picture, against a budget of %.3g left by the terrain%s)",
                  c.spheres, meshes == 1 ? "the mesh" : "each mesh", c.predicted_error, t.sun, t.sky,
                  picture_area_m2 * 1e-6, budget,
                  c.met ? "; the fewest spheres under it" : "; no count is predicted under it: the count of the least");
    return line;
}

}  // namespace ts::app
