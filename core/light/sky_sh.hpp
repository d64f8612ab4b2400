#pragma once
// SH of a sky with an explicit quadrature rule (project_sky_sh and project_diffuse_sky_sh in
// sky.hpp use default_sky_rule(sky)), and the diffuse projection with its fit kept per rule.
#include <array>
#include <vector>

#include "core/light/sky.hpp"
#include "core/light/sky_quadrature.hpp"
#include "core/sh/sh_basis.hpp"

namespace ts::light {

// The rule project_sky_sh uses: 32 Gauss-Legendre nodes in z per hemisphere x 128 azimuths
// (8192 radiance evaluations) for analytic skies. Measured against a 256 x 1024 rule,
// every coefficient of the Preetham sky is within 3e-5 of the DC term (sun 3..60 degrees up,
// T 2..8; docs/lighting.md); convergence is algebraic, not spectral, because the Perez
// exp(D gamma) term has a cone-shaped peak at the sun. For an HDR map: at least one node per
// pixel in each direction (n_phi >= width, 2 n_z >= height); an HdrSky caches its projection.
HemisphereRule default_sky_rule(const Sky& sky);

SkySh project_sky_sh(const Sky& sky, const HemisphereRule& rule);

// The sky's SH for diffuse terrain shading: bands 0..2 fitted to the irradiance of the normals
// terrain has, band 3 as project_sky_sh (diffuse_sky_fit.hpp). What <T, L> of a terrain texel
// takes; a specular lobe or a mesh takes project_sky_sh.
SkySh project_diffuse_sky_sh(const Sky& sky, const HemisphereRule& rule);

// project_diffuse_sky_sh(sky) that keeps the factors per ring of its rule: for a caller that
// projects every frame (computing the fit's factors took a quarter of the projection's time).
// With `radiance`, also project_sky_sh(sky) from the same pass over the sky's radiance.
class DiffuseSkyProjector {
public:
    SkySh project(const Sky& sky, SkySh* radiance = nullptr);
    SkySh project(const Sky& sky, const HemisphereRule& rule, SkySh* radiance);

private:
    HemisphereRule rule_{0, 0};
    std::vector<sh::ShVec> radiance_factors_, diffuse_factors_;  // per ring
};

// The sky's radiance reconstructed from its SH at a direction (sh::reconstruct per channel).
Rgb reconstruct_sky_sh(const SkySh& sh, const glm::dvec3& dir);

}  // namespace ts::light
