#include "core/render/scene_blockers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/terrain/valid_bilinear.hpp"
#include "core/util/error.hpp"

namespace ts::render {

glm::dvec2 mesh_anchor(const geo::Georef& georef, const mesh::Placement& placement, const std::string& name) {
    try {
        mesh::validate(placement);
    } catch (const InputError& e) {
        throw input_error(name, e.what());
    }
    const glm::dvec2 px = georef.lonlat_to_pixel({placement.lon_deg, placement.lat_deg});
    if (!(px.x >= 0 && px.y >= 0 && px.x <= georef.width() && px.y <= georef.height())) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "placed at %.6f,%.6f, off the DEM (pixel %.1f,%.1f of %dx%d)", placement.lon_deg,
                      placement.lat_deg, px.x, px.y, georef.width(), georef.height());
        throw input_error(name, buf);
    }
    return {px.x - 0.5, px.y - 0.5};
}

mesh::Placement placement_on_grid(const geo::Georef& georef, const mesh::Placement& placement, glm::dvec2 anchor) {
    mesh::Placement p = placement;
    if (georef.valid()) p.heading_deg += georef.grid_azimuth_of_north_deg(anchor.x + 0.5, anchor.y + 0.5);
    return p;
}

double ground_height(const terrain::HeightGrid& g, glm::dvec2 t) {
    const double x = std::clamp(t.x, 0.0, double(g.width - 1)), y = std::clamp(t.y, 0.0, double(g.height - 1));
    float fc = 0, fr = 0;
    const int c = terrain::valid_bilinear_corner(x, g.width, fc);
    const int r = terrain::valid_bilinear_corner(y, g.height, fr);
    const int c1 = std::min(c + 1, g.width - 1), r1 = std::min(r + 1, g.height - 1);
    return terrain::blend_valid_corners(g.at(c, r), g.at(c1, r), g.at(c, r1), g.at(c1, r1), fc, fr);
}

blockers::SphereBlockers place_scene_meshes(std::span<const SceneMesh> meshes, const terrain::HeightGrid& grid,
                                            const geo::Georef& georef, const blockers::SphereBlockerOptions& options,
                                            std::vector<std::string>& warnings) {
    blockers::SphereBlockers out;
    out.options = options;
    for (const SceneMesh& m : meshes) {
        const glm::dvec2 anchor = mesh_anchor(georef, m.placement, m.name);
        const double ground = ground_height(grid, anchor);
        if (m.placement.above_ground && std::isnan(ground))
            throw input_error(m.name, "an agl height over a void of the DEM: give the height above the datum");
        out.meshes.push_back(blockers::place_spheres(m.model_spheres, placement_on_grid(georef, m.placement, anchor), anchor,
                                                     std::isnan(ground) ? 0.0 : ground, m.name));
        if (m.triangles && options.sun_caster == blockers::SphereBlockerOptions::SunCaster::triangles)
            out.meshes.back().model_triangles = blockers::model_triangle_bvh(*m.triangles);
        double top = -INFINITY;
        for (const blockers::Sphere& s : out.meshes.back().spheres) top = std::max(top, s.center.z + s.radius);
        if (!std::isnan(ground) && top < ground) {
            char buf[200];
            std::snprintf(buf, sizeof buf, "%s: the mesh lies below the terrain (its top %.1f m, the ground %.1f m): "
                                           "it darkens only what lies inside it", m.name.c_str(), top, ground);
            warnings.push_back(buf);
        }
    }
    return out;
}

}  // namespace ts::render
