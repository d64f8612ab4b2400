#pragma once
// Earth curvature with standard atmospheric refraction: a point at ground distance d drops by
// d^2 / (2 R_eff) below the receiver's tangent plane, R_eff = R / (1 - k), k = 0.13 (the usual
// refraction coefficient for surveying and radio line of sight).
namespace ts::visibility {

constexpr double kEarthMeanRadiusM = 6371008.8;  // IUGG mean radius
constexpr double kRefractionCoefficient = 0.13;
constexpr double kEffectiveEarthRadiusM = kEarthMeanRadiusM / (1.0 - kRefractionCoefficient);

// 1 / (2 R_eff), or 0 without curvature: drop(d) = d * d * curvature_factor.
inline double curvature_factor(bool curvature) {
    return curvature ? 0.5 / kEffectiveEarthRadiusM : 0.0;
}

}  // namespace ts::visibility
