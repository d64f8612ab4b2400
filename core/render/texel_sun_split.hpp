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
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/light/sky.hpp"
#include "core/render/render_scene.hpp"

namespace ts::render {

struct TexelSunSplit {
    std::vector<glm::vec3> rest;        // the radiance less the sun's diffuse term
    std::vector<glm::vec3> sun_albedo;  // a = albedo E_sun / pi
    // h - e, radians, within visibility::kSunHorizonBandRad: the frame's sun_horizon() when the
    // scene keeps it (RendererOptions::keep_sun_horizon), else the one its visible fraction
    // implies (within the disc's radius). +band over voids and with the sun down.
    std::vector<float> horizon_above_sun;
};

// `radiance`: the frame the scene rendered last for `sun` under `sky` (its grid's texels).
void split_texel_sun(const Scene& scene, const SunState& sun, const light::Sky& sky,
                     std::span<const glm::vec3> radiance, TexelSunSplit& out);

}  // namespace ts::render
