#pragma once
// The sun's diffuse term shaded per pixel where one texel spans many pixels: a perspective
// view's close range and a magnified map. Blending the texels' radiance bilinearly varies the
// shading linearly across each texel and steps a shadow's edge along the texel lines; here the
// texels' radiance without their own sun term is blended, and the sun's term is put back with
// the pixel's own normal on the smooth surface (core/terrain/smooth_surface.hpp) and, where the
// four texels around the pixel disagree on the sun, the pixel's own share of the disc, marched
// towards the sun over the same surface (surface_march.hpp).
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/render/pixel_sun_blockers.hpp"
#include "core/render/surface_march.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/terrain/smooth_surface.hpp"

namespace ts::render {

// The diffuse sun term of a frame's per-texel radiance, kept apart so that each pixel shades it
// with its own normal: per texel w E_sun/pi max(0, n.s), w = albedo x the visible share of the
// sun's disc, n the texel's normal (as FrameRenderer shaded it; water, a mirror over a dark
// body, has no such term). Pointers to the frame's per-texel arrays, none copied.
struct TexelSunTerm {
    const float *albedo_r = nullptr, *albedo_g = nullptr, *albedo_b = nullptr;
    const std::uint8_t* water = nullptr;  // 1 = water; may be null (none)
    const float* visibility = nullptr;    // the sun's visible share as the frame had it (NaN: none)
    const float *nx = nullptr, *ny = nullptr, *nz = nullptr;
    glm::vec3 direction{0, 0, 1};        // towards the sun (ENU)
    glm::vec3 irradiance_over_pi{0.0f};  // E_sun / pi
    // For per-pixel shadows: the share the terrain alone leaves (null: blend `visibility`
    // instead). A pixel whose patch's 4 texels are all fully lit or all fully shaded takes that
    // without a ray; and the meshes' shadows at the pixel (may be null).
    const float* terrain_visibility = nullptr;
    const PixelSunBlockers* blockers = nullptr;
};

// The unit normal in ENU of a surface's slopes (terrain/smooth_surface.hpp) at texel-centre
// row y (rows run south: -y); straight up where it has none.
glm::vec3 slope_normal(const terrain::HeightGrid& grid, const terrain::SurfaceSample& slopes, double y);

// One frame's per-pixel sun shading over a grid.
class PixelSunShading {
public:
    // `march` null, or a term without terrain_visibility, blends the texels' visible shares
    // (per-pixel normals still); `curvature` as visibility::curvature_factor.
    PixelSunShading(const terrain::HeightGrid& grid, const SurfaceMarch* march, const TexelSunTerm& term,
                    double sun_cos_radius, double curvature);

    // Whether pixels march their own sun rays this frame (asked for, and the sun gives light).
    bool marches() const { return march_ != nullptr; }

    // Splits every texel of `texel_radiance` (the grid's) into what radiance() blends, once:
    // for a picture with more pixels than texels (a magnified map), where per pixel each of
    // its four texels would be split again. radiance() then reads the split, the same numbers.
    void split_texels(const glm::vec3* texel_radiance, int threads);

    // The radiance at texel-centre coordinates (x, y), inside the grid, where the surface's unit
    // normal is n.
    glm::vec3 radiance(const glm::vec3* texel_radiance, float x, float y, const glm::vec3& n) const;

private:
    // Texel t's radiance without its diffuse sun term (`rest`), and what the sun's term is
    // weighed by at a pixel (`weight`: the albedo, times the texel's visible share of the disc
    // unless pixels march their own).
    void split(const glm::vec3* texel_radiance, std::size_t t, glm::vec3& rest, glm::vec3& weight) const;
    // 1 or 0 where the terrain leaves the sun wholly visible or wholly hidden at the 4 corners
    // of patch (c0, r0); -1 where a shadow's edge or penumbra crosses it.
    float uniform_visibility(int c0, int r0) const;

    const terrain::HeightGrid& grid_;
    const SurfaceMarch* march_;
    const TexelSunTerm& term_;
    double sun_radius_, curvature_;
    std::vector<glm::vec3> rest_, weight_;  // split_texels(), per texel (empty: split per pixel)
};

}  // namespace ts::render
