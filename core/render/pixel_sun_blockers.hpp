#pragma once
// Mesh blockers' sun shadows at any point of the terrain's surface, for views that find shadows
// per pixel (perspective_view.hpp, pixel_sun_shadows): the fraction of the sun's disc the
// meshes leave, as visibility::BlockerSunShadow finds it for texel centres (the spheres'
// analytic cover; their triangles' where the options ask for them), at a pixel's own hit. So a
// small aircraft's shadow has its outline, not the blur of the texels it falls across.
#include <vector>

#include <glm/vec3.hpp>

#include "core/blockers/placed_spheres.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/visibility/blocker_footprint.hpp"

namespace ts::render {

class PixelSunBlockers {
public:
    // The grid and blockers must outlive it. curvature: 1 / (2 R_eff) or 0.
    PixelSunBlockers(const terrain::HeightGrid& grid, const blockers::SphereBlockers& blockers, double curvature);

    // This frame's sun (unit ENU direction): each mesh's footprint, the disc's rays.
    void set_sun(const glm::dvec3& sun);
    // The visible fraction of the disc past every mesh from the surface point at texel-centre
    // coordinates (x, y), height z metres (1 outside every footprint).
    double visible(double x, double y, double z) const;

private:
    const terrain::HeightGrid& grid_;
    const blockers::SphereBlockers& blockers_;
    double curvature_;
    visibility::HeightRange range_;
    std::vector<double> max_drop_;
    glm::dvec3 sun_{0, 0, 1};
    std::vector<visibility::TexelRect> rects_;
    std::vector<glm::dvec3> disc_;
};

}  // namespace ts::render
