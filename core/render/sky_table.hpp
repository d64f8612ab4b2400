#pragma once
// The sky's radiance tabulated over the sphere once per frame (equirectangular, bilinear
// lookups), for what needs more than order-4 SH but must not call the sky model per pixel:
// water's mirror reflection and the sky behind a perspective view.
#include <vector>

#include <glm/vec3.hpp>

#include "core/light/sky.hpp"

namespace ts::render {

class SkyTable {
public:
    // width columns over internal azimuth phi in [-pi, pi), height rows over elevation
    // from +90 (row 0) to -90 degrees; texel centres.
    explicit SkyTable(int width = 128, int height = 64);

    // Re-tabulates from `sky` (width*height model evaluations, no allocation).
    void update(const light::Sky& sky);
    // Bilinear, wrapping in azimuth; `dir` unit ENU.
    glm::vec3 lookup(const glm::vec3& dir) const;

    int width() const { return width_; }
    int height() const { return height_; }

private:
    int width_, height_;
    std::vector<glm::vec3> radiance_;
};

}  // namespace ts::render
