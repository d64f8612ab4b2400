#pragma once
// The terrain's sky light integrated over its own horizons (`--sky-light horizons`; docs/rendering.md,
// "The sky's light over the horizons"). Per texel, in S sectors of azimuth,
//
//   E / pi = 1/pi  sum_s  sum_k  n_k  C_s,k(e0_s),
//   C_s,k(e) = int_{phi in sector s} int_e^{pi/2}  L(w) w_k cos e' de' dphi,   w = (cos e' cos phi, cos e' sin phi, sin e')
//
// e0_s the mean over the sector's horizon azimuths of max(horizon, the texel's own plane), made
// once; C tabulated per frame over the elevation (the sky's lighting radiance, its ground below
// the horizontal included). n . w >= 0 above e0 (the plane bounds it), so no clamp is needed.
// Against <T, L> of the same texel (horizon_transfer.hpp) this drops only the SH truncation of
// the product: an anisotropic sky (the physical sky's bright horizon band) in 9 or 16
// coefficients times a transfer with a sharp horizon. On the Anatolia crop under a 20 degree sun
// the sky's part was off by 6.8% RMS that way against Blender Cycles (docs/rendering.md).
//
// The renderer adds it to <T_d - T_terrain, L>, where T_terrain is the same texel's exact
// projected transfer: the bounce and the mesh blockers keep their SH terms.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/light/sky.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/visibility/horizon_set.hpp"

namespace ts::render {

// Speed/accuracy knobs (`--sky-light`, `--sky-sectors`; chart in docs/rendering.md).
struct SkyLightSettings {
    // sh: <T_d, L> alone (the sky's SH times each texel's transfer); horizons: this class.
    enum class Mode { sh, horizons };
    Mode mode = Mode::horizons;
    int sectors = 16;          // S at most; the largest divisor of the horizon azimuths D up to it
    int elevation_steps = 64;  // the per-frame table's integration steps over [-90, 90] degrees
};

// The sky such a renderer takes: over the horizons the sky keeps its aureole, unless the sky's
// spec names one (`aureole=`). Moving it into the sun's beam is what SH needs (physical_sky.hpp).
light::SkyOptions sky_for(light::SkyOptions sky, const SkyLightSettings& settings);

// The sectors used for D horizon azimuths: the largest divisor of D not above `settings.sectors`.
int effective_sectors(const SkyLightSettings& settings, int directions);

class HorizonSkyLight {
public:
    // Throws std::invalid_argument when the sizes differ.
    HorizonSkyLight(const visibility::HorizonSet& horizons, const NormalField& normals, const SkyLightSettings& settings,
                    int threads);

    std::size_t texels() const { return texels_; }
    int sectors() const { return sectors_; }
    // E / pi of every texel (the sky's units; NaN for void texels) under `sky` into `out` [texels].
    void irradiance_over_pi(const light::Sky& sky, glm::vec3* out, int threads) const;

private:
    // The per-frame table: C_s,k at node m, [(s * (steps + 1) + m) * 3 + k].
    std::vector<glm::vec3> table(const light::Sky& sky) const;

    std::size_t texels_ = 0;
    int sectors_ = 0, directions_ = 0, steps_ = 0;
    const NormalField& normals_;
    std::vector<std::uint16_t> node_;  // [texel][s]: e0_s as the nearest look-up node (0xffff: void)
};

}  // namespace ts::render
