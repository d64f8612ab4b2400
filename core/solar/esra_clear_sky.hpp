#pragma once
// The ESRA clear-sky model as GRASS r.sun uses it (Rigollier, Bauer & Wald, "On the clear sky
// model of the ESRA", Solar Energy 68(1) 33-48 (2000); Hofierka & Suri, "The solar radiation
// model for Open source GIS: implementation and applications", Proc. Open Source GIS - GRASS
// users conference, Trento (2002); Suri & Hofierka, Transactions in GIS 8(2) 175-190 (2004)).
// Each function is one formula of docs/insolation.md, with r.sun's coefficients, so a beam or
// diffuse value here can be compared with r.sun's term for term.
namespace ts::solar {

// r.sun's solar constant, W/m^2.
inline constexpr double kSolarConstantWm2 = 1367.0;

// Extraterrestrial irradiance normal to the beam on day `day_of_year` (1..366): the solar
// constant times the eccentricity correction 1 + 0.03344 cos(2 pi j / 365.25 - 0.048869).
double extraterrestrial_normal_irradiance(double day_of_year);

// The sun's altitude corrected for refraction as ESRA and r.sun do inside the air mass, h0 +
// 0.061359 (0.1594 + 1.123 h0 + 0.065656 h0^2) / (1 + 28.9344 h0 + 277.3971 h0^2), radians.
double esra_refracted_altitude_rad(double altitude_rad);

// Relative optical air mass (Kasten & Young 1989) with the elevation correction p/p0 =
// exp(-z / 8434.5): (p/p0) / (sin h0ref + 0.50572 (h0ref_deg + 6.07995)^-1.6364).
double relative_optical_air_mass(double altitude_rad, double elevation_m);

// Rayleigh optical thickness at air mass m (Kasten 1996, as revised for ESRA): for m <= 20,
// 1 / (6.6296 + 1.7513 m - 0.1202 m^2 + 0.0065 m^3 - 0.00013 m^4); beyond, 1 / (10.4 + 0.718 m).
double rayleigh_optical_thickness(double air_mass);

// Beam irradiance normal to the sun's rays, W/m^2: G0 exp(-0.8662 TL m deltaR(m)); 0 when the
// (unrefracted) altitude is not above 0, as r.sun.
double beam_normal_irradiance(double g0, double linke, double altitude_rad, double elevation_m);

// The diffuse transmission function at zenith Tn(TL) = -0.015843 + 0.030543 TL + 0.0003797 TL^2.
double diffuse_transmission(double linke);
// The diffuse angular function Fd(h0) = A1 + A2 sin h0 + A3 sin^2 h0 with ESRA's A1 (floored so
// A1 Tn >= 0.0022), A2, A3 polynomials in TL.
double diffuse_angular_function(double linke, double altitude_rad);
// Diffuse irradiance on a horizontal plane under an open sky, W/m^2: G0 Tn(TL) Fd(h0); 0 when the
// altitude is not above 0.
double diffuse_horizontal_irradiance(double g0, double linke, double altitude_rad);

}  // namespace ts::solar
