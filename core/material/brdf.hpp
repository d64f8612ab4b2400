#pragma once
// The BRDFs of the lecture "Material Models" (Slusallek) as plain functions of the incident
// direction wi (towards the light), the outgoing direction wo (towards the viewer) and the
// normal n, all unit vectors. f_r in 1/sr; 0 when wi or wo is below the surface.
// Which models are reciprocal and energy conserving is stated per function and tested.
#include <glm/vec3.hpp>

namespace ts::material {

// rho / pi. Reciprocal; directional albedo = rho.
double lambert(double rho);

// Lecture's Phong: ks (R(I).V)^ke / (I.N), so that L_r = L_i ks cos^ke. Neither reciprocal nor
// energy conserving (as the lecture says).
double phong(const glm::dvec3& wi, const glm::dvec3& wo, const glm::dvec3& n, double ks, double ke);
// Normalised (modified) Phong [Lewis 1994]: ks (ke + 2)/(2 pi) max(R(I).V, 0)^ke. Reciprocal;
// albedo = ks at normal incidence, <= ks elsewhere (the lobe is cut by the horizon).
double phong_normalized(const glm::dvec3& wi, const glm::dvec3& wo, const glm::dvec3& n, double ks, double ke);

// Lecture's Blinn-Phong: ks (H.N)^ke / (I.N). Not reciprocal.
double blinn_phong(const glm::dvec3& wi, const glm::dvec3& wo, const glm::dvec3& n, double ks, double ke);
// Normalised Blinn-Phong: ks (ke + 8)/(8 pi) (H.N)^ke [Akenine-Moller et al., RTR]. Reciprocal;
// the normalisation is approximate and overshoots near normal incidence: albedo up to 1.06 ks
// (measured at ke = 20); use ks <= 0.94 for strict energy conservation.
double blinn_phong_normalized(const glm::dvec3& wi, const glm::dvec3& wo, const glm::dvec3& n, double ks, double ke);

// Isotropic Ward: rho_d/pi + rho_s exp(-tan^2(h)/sigma^2) / (4 pi sigma^2 sqrt(cos_i cos_o)).
// Reciprocal. Not energy conserving at grazing angles for rough surfaces (the 1/sqrt(cos cos)
// factor grows without bound); tested within its usual range (sigma <= 0.2).
double ward(const glm::dvec3& wi, const glm::dvec3& wo, const glm::dvec3& n, double rho_d, double rho_s, double sigma);

enum class Distribution { beckmann, ggx };
enum class Geometry { smith, vgroove };
enum class FresnelModel { dielectric, conductor, schlick, none };

struct CookTorrance {
    Distribution distribution = Distribution::ggx;
    Geometry geometry = Geometry::smith;
    FresnelModel fresnel = FresnelModel::dielectric;
    double roughness = 0.3;  // Beckmann m (RMS slope) or GGX alpha
    double eta = 1.5;        // dielectric index (from air) or conductor real part
    double k = 0.0;          // conductor imaginary part
    double f0 = 0.04;        // Schlick's normal-incidence reflectance
    double kd = 0.0;         // weight of the Lambertian term rho_d / pi
    double rho_d = 0.0;
    double ks = 1.0;  // weight of the glossy term
};

// kd rho_d / pi + ks F D G / (4 (N.I)(N.O)) [Cook and Torrance 1982; Walter et al. 2007].
// The lecture writes pi instead of 4 in the denominator, which belongs with the original
// paper's unnormalised Beckmann D; with the normalised D used here it must be 4 (else the
// albedo exceeds 1 by 4/pi). Reciprocal; with Smith G albedo <= 1 (tested).
double cook_torrance(const glm::dvec3& wi, const glm::dvec3& wo, const glm::dvec3& n, const CookTorrance& p);

}  // namespace ts::material
