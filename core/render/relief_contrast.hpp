#pragma once
// Relief contrast for maps (render --relief-contrast): under a soft light (an overcast sky) the
// shading of a slope differs from the flat by 10-20%, less than the albedos of the land cover
// differ, so the picture reads as a land-cover map. This stretches the shading alone, not the
// albedo: each land texel's irradiance E = radiance / albedo (per channel, diffuse texels) is
// raised to a power k about the picture's log-average E_ref,
//   E' = E_ref (E / E_ref)^k,   radiance' = albedo * E',
// so slopes, hollows and shadows get k times their contrast in stops while the colours of the
// ground stay as they were. Automatic: k makes the 5th-95th percentile spread of log2 E at least
// `target_stops` (a sunlit map with shadows already has it: k = 1), at most `max_k`.
// Water (a mirror, not albedo times light) and texels with no albedo are left as they are.
// With soften_albedo (automatic mode), a light soft enough to need k > 1 also gets its land
// albedo contrast compressed by another 1/k (compressed_albedo, material.hpp): the colours of
// the land cover then differ less than the stretched shading does, so the relief reads first.
#include <vector>

#include <glm/vec3.hpp>

#include "core/material/material.hpp"

namespace ts::render {

struct ReliefContrast {
    bool automatic = true;
    double k = 1.0;             // when !automatic; 1 = the physical picture
    double target_stops = 1.5;  // automatic: the shading's 5-95% spread to reach
    double max_k = 8.0;
    bool soften_albedo = true;  // automatic only
};

struct ReliefContrastApplied {
    double k = 1.0;               // the shading's stretch (1 = none)
    double albedo_factor = 1.0;   // the further albedo contrast applied (1 = none)
};

ReliefContrastApplied apply_relief_contrast(std::vector<glm::vec3>& radiance, const MaterialRaster& materials,
                             const ReliefContrast& options);

}  // namespace ts::render
