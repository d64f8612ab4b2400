#pragma once
// Fresnel reflectance for unpolarised light, F = (r_par^2 + r_perp^2) / 2 (lecture "Material
// Models", slides "Dielectrics" and "Electric Conductors"). cos_i is the cosine between the
// incident direction and the (micro)surface normal, in [0, 1].
namespace ts::material {

// Exact, for a dielectric interface eta_i -> eta_t; total internal reflection gives 1.
double fresnel_dielectric(double cos_i, double eta_i, double eta_t);

// Exact, for a conductor with complex index eta + i k seen from vacuum/air (Born and Wolf;
// evaluated in complex arithmetic: cos_t = sqrt(1 - sin^2_i / (eta + i k)^2)).
double fresnel_conductor(double cos_i, double eta, double k);

// The lecture's closed form for conductors (r_par^2, r_perp^2 in eta, k, cos_i): exact at
// normal incidence, an approximation elsewhere (it drops the sin^2 term inside cos_t).
double fresnel_conductor_lecture(double cos_i, double eta, double k);

// Schlick's approximation F0 + (1 - F0)(1 - cos)^5, and F0 of a dielectric ((n-1)/(n+1))^2.
double fresnel_schlick(double cos_i, double f0);
double fresnel_f0(double eta_i, double eta_t);

}  // namespace ts::material
