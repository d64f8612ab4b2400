#pragma once
// The reference the renderer is measured against (docs/accuracy.md): per receiver texel, the
// sun and the sky ray-traced with the same BRDFs (core/material, docs/rendering.md), with
// none of the renderer's approximations:
//  - visibility by marching the bilinear height surface from the texel centre in steps of
//    1/4 texel out to the grid's edge with Earth curvature (visibility::march_max_slope, the
//    horizon methods' reference), at `azimuths` directions (>= 720), instead of D exact-sweep
//    horizons turned into order-4 log-SH;
//  - the sky integrated over the hemisphere of the normal in the world frame: per azimuth, the
//    elevations from max(horizon, the normal's horizon) to the zenith, split where the Phong
//    lobe's support begins, Gauss-Legendre on pieces of at most `max_piece_deg`, with
//    radiance from light::Sky::radiance itself (no SH, no table);
//  - the sun: the fraction of its disc above the raymarched horizon in the sun's own azimuth
//    x BRDF at the sun's direction x max(0, n.s) x the sun's irradiance;
//  - water: the Fresnel mirror (n = 1.333) of Sky::radiance in the mirror direction, hidden
//    by the raymarched horizon in that direction, over a dark diffuse body (albedo 0.02).
// Normals, materials and the view are inputs: the bench passes the renderer's own
// (render::terrain_normals, rule_materials), so only lighting and visibility differ. Water
// texels are shaded flat (normal straight up), as the renderer does.
#include <cstddef>
#include <glm/vec3.hpp>
#include <vector>

#include "core/light/sky.hpp"
#include "core/render/frame_renderer.hpp"
#include "core/material/material.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/visibility/row_metrics.hpp"

namespace ts::render {

struct ReferenceOptions {
    int azimuths = 720;           // horizon azimuths phi_k = 2 pi (k + 1/2) / K (midpoint rule)
    double max_piece_deg = 10.0;  // elevation pieces of at most this ...
    int nodes_per_piece = 6;      // ... each integrated by Gauss-Legendre with this many nodes
    bool curvature = true;        // Earth curvature with refraction, as the renderer
    int threads = 0;
};

// Radiance and what went into it, per reference texel (linear RGB, the sky's units).
struct ReferenceSample {
    glm::vec3 radiance{0.0f};
    glm::vec3 sky_irradiance{0.0f};  // E_sky = integral of L V max(0, n.w) over the sphere
    float sun_fraction = 0.0f;       // visible fraction of the sun's disc
};

class ReferenceShader {
public:
    // Raymarches `azimuths` horizons for each listed texel (row * width + col; void texels
    // give NaN results). grid, materials, normals and view must outlive the shader.
    ReferenceShader(const terrain::HeightGrid& grid, const MaterialRaster& materials, const NormalField& normals,
                    const ViewDirections& view, std::vector<std::size_t> texels, const ReferenceOptions& options = {});

    const std::vector<std::size_t>& texels() const { return texels_; }
    // Horizon elevation (radians) of listed texel k in azimuth index a.
    float horizon(std::size_t k, int a) const { return horizons_[k * std::size_t(options_.azimuths) + std::size_t(a)]; }

    // Shades every listed texel under `sky` (its sun disc gives the sun's irradiance and radius)
    // with the sun at `sun` (user angles; its direction must be the sky's).
    std::vector<ReferenceSample> render(const light::Sky& sky, const SunState& sun) const;

private:
    ReferenceSample shade(std::size_t k, const light::Sky& sky, const SunState& sun) const;

    const terrain::HeightGrid& grid_;
    const MaterialRaster& materials_;
    const NormalField& normals_;
    const ViewDirections& view_;
    std::vector<std::size_t> texels_;
    ReferenceOptions options_;
    std::vector<float> horizons_;  // [texel][azimuth]
    visibility::RowMetrics metrics_;
    double curvature_ = 0;
    float z_top_ = 0;
};

// The reference sun visibility of every texel of the grid (row-major; NaN for voids): the
// disc fraction above the horizon raymarched in the sun's azimuth (march stopped early once
// the answer is known to be outside the disc, which does not change the fraction).
std::vector<float> reference_sun_visibility(const terrain::HeightGrid& grid, double sun_azimuth_deg,
                                            double sun_elevation_deg, double sun_radius_rad, bool curvature,
                                            int threads = 0);

}  // namespace ts::render
