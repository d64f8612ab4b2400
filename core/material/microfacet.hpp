#pragma once
// Microfacet distributions and geometry terms (lecture "Microfacet Distribution Functions",
// "Geometric Attenuation Factor"; Walter et al. 2007 for GGX and the Smith forms).
// Distributions are normalised so that the projected microfacet area is one:
// int D(h) (n . h) dw_h = 1. cos_h is n . h.
namespace ts::material {

// Beckmann: exp(-tan^2 a / m^2) / (pi m^2 cos^4 a), m the RMS slope.
double beckmann_d(double cos_h, double m);
// GGX / Trowbridge-Reitz: alpha^2 / (pi cos^4 a (alpha^2 + tan^2 a)^2).
double ggx_d(double cos_h, double alpha);

// Smith masking for one direction at angle theta to the normal (cos_v = n . v):
// G1 = 1 / (1 + Lambda). Beckmann: Lambda = (erf(a) - 1)/2 + exp(-a^2) / (2 a sqrt(pi)),
// a = 1 / (m tan theta). GGX: Lambda = (sqrt(1 + alpha^2 tan^2 theta) - 1) / 2.
double smith_g1_beckmann(double cos_v, double m);
double smith_g1_ggx(double cos_v, double alpha);

// Torrance-Sparrow V-groove: min(1, 2 (n.h)(n.o)/(o.h), 2 (n.h)(n.i)/(o.h)) (o.h = i.h).
double vgroove_g(double n_h, double n_i, double n_o, double o_h);

}  // namespace ts::material
