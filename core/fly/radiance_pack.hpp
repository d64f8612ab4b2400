#pragma once
// Per-texel light as the flythrough's shaders read it (gpu/fly/fly_frame.glsl): Radiance, two
// words a texel, packHalf2x16 of (r, g) and of (b, extra); TerrainSun, four words, the sun's
// diffuse term split from it (core/render/texel_sun_split.hpp) for the fragments to shade.
#include <cmath>
#include <cstdint>

#include <glm/packing.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ts::fly {

// Not finite becomes 0, negative is clamped to 0.
inline void pack_radiance(glm::vec3 c, float extra, std::uint32_t* out) {
    const bool finite = std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z);
    const glm::vec3 v = finite ? glm::max(c, glm::vec3(0.0f)) : glm::vec3(0.0f);
    out[0] = glm::packHalf2x16(glm::vec2(v.x, v.y));
    out[1] = glm::packHalf2x16(glm::vec2(v.z, extra));
}

// a = albedo E_sun / pi and the open-sky fraction as pack_radiance packs a colour and its extra,
// then the unit normal's east and north components (its up one is implied, >= 0) and the
// horizon in the sun's azimuth above the sun (radians).
inline void pack_sun_light(glm::vec3 a, float open_sky, glm::vec3 normal, float horizon_above_sun, std::uint32_t* out) {
    pack_radiance(a, open_sky, out);
    const bool finite = std::isfinite(normal.x) && std::isfinite(normal.y);
    out[2] = glm::packHalf2x16(finite ? glm::vec2(normal.x, normal.y) : glm::vec2(0.0f));
    out[3] = glm::packHalf2x16(glm::vec2(std::isfinite(horizon_above_sun) ? horizon_above_sun : 0.0f, 0.0f));
}

}  // namespace ts::fly
