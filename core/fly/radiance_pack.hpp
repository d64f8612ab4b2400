#pragma once
// Radiance as the flythrough's shaders read it: two words a texel, packHalf2x16 of (r, g) and of
// (b, extra); not finite becomes 0, negative is clamped to 0.
#include <cmath>
#include <cstdint>

#include <glm/packing.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ts::fly {

inline void pack_radiance(glm::vec3 c, float extra, std::uint32_t* out) {
    const bool finite = std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z);
    const glm::vec3 v = finite ? glm::max(c, glm::vec3(0.0f)) : glm::vec3(0.0f);
    out[0] = glm::packHalf2x16(glm::vec2(v.x, v.y));
    out[1] = glm::packHalf2x16(glm::vec2(v.z, extra));
}

}  // namespace ts::fly
