#pragma once
// A magnified map's sun shaded per pixel (pixel_sun_shading.hpp): where a map's pixels are
// smaller than the DEM's texels (render --size beyond the grid, an --extent zoomed in), a
// bilinear blend of the texels' radiance is a blur with a star at every texel and shadow edges
// stepped along the texel lines. Each pixel instead takes its own normal (the smoothed slope,
// terrain::smooth_slope, made once per view) and, with per-pixel shadows, its own share of the
// sun's disc.
// What the pixel keeps from the blend: the sky's light, the bounce, the albedo, water.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/render/pixel_sun_shading.hpp"
#include "core/render/surface_march.hpp"
#include "core/terrain/height_grid.hpp"

namespace ts::render {

// Whether pixels at these texel-centre coordinates (row-major width x height; x < -0.75: off the
// DEM) are smaller than the texels: their mean step along rows or along columns below one texel.
bool pixels_magnify(const std::vector<glm::vec2>& at, int width, int height);

class MapPixelSun {
public:
    // `at`: each pixel's texel-centre coordinates (row-major width x height; x < -0.75: off the
    // DEM); `pixel_shadows`: march the pixels' own sun rays where their texels disagree (else
    // blend the texels' shares).
    MapPixelSun(const terrain::HeightGrid& grid, std::vector<glm::vec2> at, int width, int height, bool pixel_shadows,
                double curvature, int threads);

    // Shades into `rgb` (one per pixel) each pixel on the DEM whose four texels all have
    // radiance, and marks it in `shaded` (1, others 0): void and outside corners are the
    // caller's to blend.
    void shade(const std::vector<glm::vec3>& texel_radiance, const TexelSunTerm& term, double sun_cos_radius,
               std::vector<glm::vec3>& rgb, std::vector<std::uint8_t>& shaded) const;

private:
    const terrain::HeightGrid& grid_;
    std::vector<glm::vec2> at_;      // clamped onto the grid's texel centres
    std::vector<glm::vec3> normal_;  // from the smoothed slope (terrain::smooth_slope), per pixel
    std::unique_ptr<SurfaceMarch> march_;
    int width_, height_;
    double curvature_;
    int threads_;
};

}  // namespace ts::render
