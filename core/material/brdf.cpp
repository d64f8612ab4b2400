#include "core/material/brdf.hpp"

#include <cmath>
#include <glm/geometric.hpp>

#include "core/material/fresnel.hpp"
#include "core/material/microfacet.hpp"
#include "core/util/angles.hpp"

namespace ts::material {
namespace {


glm::dvec3 reflect_about(const glm::dvec3& i, const glm::dvec3& n) {
    return -i + 2.0 * glm::dot(i, n) * n;
}

bool above(const glm::dvec3& wi, const glm::dvec3& wo, const glm::dvec3& n) {
    return glm::dot(wi, n) > 0.0 && glm::dot(wo, n) > 0.0;
}

}  // namespace

double lambert(double rho) {
    return rho / kPi;
}

double phong(const glm::dvec3& wi, const glm::dvec3& wo, const glm::dvec3& n, double ks, double ke) {
    if (!above(wi, wo, n)) return 0.0;
    const double rv = glm::dot(reflect_about(wi, n), wo);
    return rv > 0.0 ? ks * std::pow(rv, ke) / glm::dot(wi, n) : 0.0;
}

double phong_normalized(const glm::dvec3& wi, const glm::dvec3& wo, const glm::dvec3& n, double ks, double ke) {
    if (!above(wi, wo, n)) return 0.0;
    const double rv = glm::dot(reflect_about(wi, n), wo);
    return rv > 0.0 ? ks * (ke + 2.0) / (2.0 * kPi) * std::pow(rv, ke) : 0.0;
}

double blinn_phong(const glm::dvec3& wi, const glm::dvec3& wo, const glm::dvec3& n, double ks, double ke) {
    if (!above(wi, wo, n)) return 0.0;
    const glm::dvec3 h = glm::normalize(wi + wo);
    return ks * std::pow(std::fmax(glm::dot(h, n), 0.0), ke) / glm::dot(wi, n);
}

double blinn_phong_normalized(const glm::dvec3& wi, const glm::dvec3& wo, const glm::dvec3& n, double ks, double ke) {
    if (!above(wi, wo, n)) return 0.0;
    const glm::dvec3 h = glm::normalize(wi + wo);
    return ks * (ke + 8.0) / (8.0 * kPi) * std::pow(std::fmax(glm::dot(h, n), 0.0), ke);
}

double ward(const glm::dvec3& wi, const glm::dvec3& wo, const glm::dvec3& n, double rho_d, double rho_s, double sigma) {
    if (!above(wi, wo, n)) return 0.0;
    const glm::dvec3 h = glm::normalize(wi + wo);
    const double ch = glm::dot(h, n);
    const double tan2 = (1.0 - ch * ch) / (ch * ch);
    const double spec =
        std::exp(-tan2 / (sigma * sigma)) / (4.0 * kPi * sigma * sigma * std::sqrt(glm::dot(wi, n) * glm::dot(wo, n)));
    return rho_d / kPi + rho_s * spec;
}

double cook_torrance(const glm::dvec3& wi, const glm::dvec3& wo, const glm::dvec3& n, const CookTorrance& p) {
    if (!above(wi, wo, n)) return 0.0;
    const glm::dvec3 h = glm::normalize(wi + wo);
    const double n_i = glm::dot(n, wi), n_o = glm::dot(n, wo), n_h = glm::dot(n, h), o_h = glm::dot(wo, h);
    const double d = p.distribution == Distribution::beckmann ? beckmann_d(n_h, p.roughness) : ggx_d(n_h, p.roughness);
    double g = 0.0;
    if (p.geometry == Geometry::vgroove) {
        g = vgroove_g(n_h, n_i, n_o, o_h);
    } else if (p.distribution == Distribution::beckmann) {
        g = smith_g1_beckmann(n_i, p.roughness) * smith_g1_beckmann(n_o, p.roughness);
    } else {
        g = smith_g1_ggx(n_i, p.roughness) * smith_g1_ggx(n_o, p.roughness);
    }
    double f = 1.0;
    switch (p.fresnel) {
        case FresnelModel::dielectric:
            f = fresnel_dielectric(o_h, 1.0, p.eta);
            break;
        case FresnelModel::conductor:
            f = fresnel_conductor(o_h, p.eta, p.k);
            break;
        case FresnelModel::schlick:
            f = fresnel_schlick(o_h, p.f0);
            break;
        case FresnelModel::none:
            f = 1.0;
            break;
    }
    return p.kd * p.rho_d / kPi + p.ks * f * d * g / (4.0 * n_i * n_o);
}

}  // namespace ts::material
