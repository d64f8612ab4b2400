#pragma once
// The sky's radiance tabulated over directions once per frame, for what needs more than order-4
// SH but must not call the sky model per pixel: water's mirror reflection and the sky behind a
// perspective view (core/render), the flythrough's background and aerial perspective (its
// shaders read the same table: core/fly/fly_sky.hpp, gpu/fly/fly_frame.glsl).
//
// Columns over internal azimuth phi, counter-clockwise from east (core/geo/azimuth.hpp), wrapping
// around the circle; rows over elevation. Bilinear in between, clamped in elevation.
#include <limits>
#include <vector>

#include <glm/vec3.hpp>

#include "core/light/sky.hpp"

namespace ts::light {

// Where a table's samples lie. Column a is at phi = phi_begin + 2 pi (a + o) / azimuths and row e
// at first_el + (last_el - first_el) (e + o) / n, with o = 0.5 and n = elevations for texel
// centres, o = 0 and n = elevations - 1 for nodes (the first and last rows on first_el, last_el).
struct SkyGrid {
    int azimuths = 128, elevations = 64;
    double phi_begin = 0;            // radians
    double first_el = 0, last_el = 0;  // radians, row 0 and the far edge
    bool texel_centres = true;
    // The sky is sampled at no lower elevation than this (the table then holds the horizon's
    // radiance below it, instead of the model's ground light).
    double lowest_sampled_el = -std::numeric_limits<double>::infinity();

    // The whole sphere in texel centres: phi from -pi, row 0 at the zenith down to the nadir;
    // at least 4 x 2.
    static SkyGrid whole_sphere(int azimuths, int elevations);
};

class SkyTable {
public:
    explicit SkyTable(const SkyGrid& grid);

    // Re-tabulates from `sky` (azimuths * elevations model evaluations, no allocation).
    void update(const Sky& sky);
    // Bilinear, wrapping in azimuth, clamped in elevation; `dir` unit ENU.
    glm::vec3 lookup(const glm::vec3& dir) const;

    const SkyGrid& grid() const { return grid_; }
    int width() const { return grid_.azimuths; }
    int height() const { return grid_.elevations; }
    // [row][column], row-major.
    const std::vector<Rgb>& radiance() const { return radiance_; }

private:
    SkyGrid grid_;
    std::vector<Rgb> radiance_;
};

}  // namespace ts::light
