#pragma once
// A map frame's per-texel radiance split so that a view can shade the sun's diffuse term per
// pixel, between texel centres (the flythrough's fragments):
//
//     radiance = rest + a max(0, n.s) F((e - h) / r)
//
// with a = albedo E_sun / pi (rgb), n the texel's normal, s the sun's direction, h - e the
// texel's horizon in the sun's azimuth above the sun's elevation, F the visible fraction of the
// disc of radius r (core/visibility/sun_disc_shared.h). A view interpolates rest, a, n and h - e
// and evaluates the rest per pixel: a shadow's edge falls where the interpolated horizon crosses
// the sun, inside the texels, rather than on a texel-wide ramp of blended radiance. At a texel
// centre both sides agree; rest keeps the sky's, the bounce's and the specular terms.
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "core/light/sky.hpp"
#include "core/render/render_scene.hpp"

namespace ts::render {

// One texel's radiance, split.
struct TexelSunLight {
    glm::vec3 rest{0.0f};        // the radiance less the sun's diffuse term
    glm::vec3 sun_albedo{0.0f};  // a = albedo E_sun / pi
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    // h - e, radians, within visibility::kSunHorizonBandRad: the frame's sun_horizon() when the
    // scene keeps it (RendererOptions::keep_sun_horizon), else the one its visible fraction
    // implies (within the disc's radius). +band over voids and with the sun down.
    float horizon_above_sun = 0.0f;
};

// Splits the texels of the frame the scene rendered last for `sun` under `sky`, one at a time,
// so a caller splits only the texels it keeps (a detail tile: its samples, not its window's halo)
// and packs them as it goes. The scene must outlive it and not render another frame meanwhile.
class TexelSunSplitter {
public:
    TexelSunSplitter(const Scene& scene, const SunState& sun, const light::Sky& sky);
    // `radiance`: the frame's radiance at texel `t` of the scene's grid.
    TexelSunLight operator()(std::size_t t, glm::vec3 radiance) const;

private:
    const MaterialRaster& materials_;
    const NormalField& normals_;
    const std::vector<float>& sun_vis_;
    const std::vector<float>& horizon_;
    glm::vec3 sun_dir_, e_over_pi_;
    double sun_radius_rad_;
};

}  // namespace ts::render
