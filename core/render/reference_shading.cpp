// The ray-traced reference (reference_shading.hpp): brute force on purpose, so that each
// piece can be checked by eye against the formulas in docs/rendering.md.
#include "core/render/reference_shading.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/geo/azimuth.hpp"
#include "core/material/fresnel.hpp"
#include "core/sh/gauss_legendre.hpp"
#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/visibility/bilinear_march.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/row_metrics.hpp"
#include "core/visibility/sun_visibility.hpp"

namespace ts::render {
namespace {

constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

glm::dvec3 unit(const glm::dvec3& v) {
    const double len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return len > 0 ? v / len : glm::dvec3(0, 0, 1);
}

// Horizon elevation (radians) from a march's best slope; no surface at all in that direction
// (a receiver on the grid's edge facing out) counts as 0, the horizon methods' convention.
double horizon_from_slope(double slope) {
    return slope == -kInf ? 0.0 : std::atan(slope);
}

// The march and the grid's constants it needs.
struct Marcher {
    const terrain::HeightGrid& grid;
    const visibility::RowMetrics& metrics;
    double curvature;
    float z_top;

    double horizon(int col, int row, float z0, double phi) const {
        return horizon_from_slope(
            visibility::march_max_slope(grid, metrics, curvature, z_top, col, row, z0, std::cos(phi), std::sin(phi)));
    }

    // The sun's visible fraction at one texel. The march may stop once the horizon is known to
    // be above the disc or below it; below is only used when the disc is wholly above 0, so a
    // march that saw no surface (horizon 0 by convention) gives the same fraction either way.
    float sun_fraction(int col, int row, float z0, double phi, double elevation, double radius) const {
        constexpr double kSlack = 1e-6;  // rad, beyond float rounding of the angles
        const double lo = elevation - radius - kSlack, hi = elevation + radius + kSlack;
        const double band_lo = lo > 0 ? std::tan(lo) : -kInf;
        const double band_hi = hi < kPi / 2 ? std::tan(hi) : kInf;
        const double slope = visibility::march_max_slope(grid, metrics, curvature, z_top, col, row, z0, std::cos(phi),
                                                         std::sin(phi), kInf, band_lo, band_hi);
        return float(visibility::sun_disc_visible_fraction(horizon_from_slope(slope), elevation, radius));
    }
};

const terrain::HeightGrid& checked(const terrain::HeightGrid& grid) {
    if (grid.width < 1 || grid.height < 1 || grid.z.size() != std::size_t(grid.width) * std::size_t(grid.height))
        throw InputError("reference: height grid empty or inconsistent");
    return grid;
}

}  // namespace

ReferenceShader::ReferenceShader(const terrain::HeightGrid& grid, const MaterialRaster& materials,
                                 const NormalField& normals, const ViewDirections& view,
                                 std::vector<std::size_t> texels, const ReferenceOptions& options)
    : grid_(checked(grid)),
      materials_(materials),
      normals_(normals),
      view_(view),
      texels_(std::move(texels)),
      options_(options),
      metrics_(grid),
      curvature_(visibility::curvature_factor(options.curvature)),
      z_top_(visibility::highest_height(grid)) {
    const std::size_t n = std::size_t(grid.width) * std::size_t(grid.height);
    if (materials.size() != n || normals.x.size() != n || (!view.per_texel.empty() && view.per_texel.size() != n))
        throw InputError("reference: materials, normals and view must have one entry per texel of the grid");
    if (options_.azimuths < 4 || options_.nodes_per_piece < 1 || !(options_.max_piece_deg > 0))
        throw InputError("reference: azimuths >= 4, nodes_per_piece >= 1 and max_piece_deg > 0 are required");
    for (std::size_t t : texels_)
        if (t >= n) throw InputError("reference: texel index " + std::to_string(t) + " outside the grid");
    const Marcher m{grid, metrics_, curvature_, z_top_};
    const int K = options_.azimuths;
    horizons_.assign(texels_.size() * std::size_t(K), kNaNf);
    parallel_for(int(texels_.size()), thread_count(options_.threads), [&](int k, int) {
        const std::size_t t = texels_[std::size_t(k)];
        const int col = int(t % std::size_t(grid.width)), row = int(t / std::size_t(grid.width));
        const float z0 = grid.z[t];
        if (std::isnan(z0)) return;
        for (int a = 0; a < K; ++a)
            horizons_[std::size_t(k) * K + std::size_t(a)] = float(m.horizon(col, row, z0, 2 * kPi * (a + 0.5) / K));
    });
}

std::vector<ReferenceSample> ReferenceShader::render(const light::Sky& sky, const SunState& sun) const {
    std::vector<ReferenceSample> out(texels_.size());
    parallel_for(int(texels_.size()), thread_count(options_.threads),
                 [&](int k, int) { out[std::size_t(k)] = shade(std::size_t(k), sky, sun); });
    return out;
}

ReferenceSample ReferenceShader::shade(std::size_t k, const light::Sky& sky, const SunState& sun) const {
    const std::size_t t = texels_[k];
    const int col = int(t % std::size_t(grid_.width)), row = int(t / std::size_t(grid_.width));
    const float z0 = grid_.z[t];
    ReferenceSample res;
    if (std::isnan(z0)) {
        res.radiance = res.sky_irradiance = glm::vec3(kNaNf);
        res.sun_fraction = kNaNf;
        return res;
    }
    const bool water = materials_.water[t] != 0;
    const glm::dvec3 n = water ? glm::dvec3(0, 0, 1) : unit({normals_.x[t], normals_.y[t], normals_.z[t]});
    const glm::dvec3 v = unit(glm::dvec3(view_.per_texel.empty() ? view_.uniform : view_.per_texel[t]));
    const glm::dvec3 r = unit(2.0 * glm::dot(n, v) * n - v);
    const double ks = water ? 0.0 : materials_.ks[t];
    const double alpha = materials_.alpha[t];
    const double phong_norm = (alpha + 1) / (2 * kPi);

    // Sky: per azimuth wedge (midpoint rule, the wedge's horizon), elevations from the higher of
    // the horizon and the normal's own horizon to the zenith. Pieces end where the Phong lobe's
    // support begins (a kink), then are cut to at most max_piece_deg for Gauss-Legendre.
    const int K = options_.azimuths;
    const double dphi = 2 * kPi / K;
    const sh::GaussLegendre gl = sh::gauss_legendre(options_.nodes_per_piece);
    const double max_piece = options_.max_piece_deg * kPi / 180.0;
    glm::dvec3 e_sky(0.0), s_sky(0.0);
    for (int a = 0; a < K; ++a) {
        const double phi = (a + 0.5) * dphi, c = std::cos(phi), s = std::sin(phi);
        // n.w = an cos(theta) + bn sin(theta) > 0 above theta_n (bn = n.z > 0 on terrain).
        const double an = n.x * c + n.y * s, bn = n.z;
        const double theta_n = std::atan2(-an, bn);
        const double lo = std::max(double(horizon(k, a)), theta_n), hi = kPi / 2;
        if (!(lo < hi)) continue;
        double cuts[3] = {lo, hi, hi};
        int n_cuts = 2;
        if (ks > 0) {
            const double ar = r.x * c + r.y * s, br = r.z;
            if (br != 0) {
                const double theta_r = std::atan(-ar / br);
                if (theta_r > lo && theta_r < hi) cuts[1] = theta_r, cuts[2] = hi, n_cuts = 3;
            }
        }
        for (int p = 0; p + 1 < n_cuts; ++p) {
            const double a0 = cuts[p], a1 = cuts[p + 1];
            const int m = std::max(1, int(std::ceil((a1 - a0) / max_piece)));
            const double h = (a1 - a0) / m;
            for (int j = 0; j < m; ++j) {
                const double mid = a0 + (j + 0.5) * h;
                for (std::size_t q = 0; q < gl.nodes.size(); ++q) {
                    const double theta = mid + 0.5 * h * gl.nodes[q];
                    const double ct = std::cos(theta), st = std::sin(theta);
                    const glm::dvec3 w(ct * c, ct * s, st);
                    const double cos_n = std::max(0.0, an * ct + bn * st);
                    // Solid angle element cos(theta) dtheta dphi.
                    const double weight = 0.5 * h * gl.weights[q] * ct * dphi;
                    const glm::dvec3 radiance(sky.lighting_radiance(w));
                    e_sky += radiance * (cos_n * weight);
                    if (ks > 0) {
                        const double cos_r = glm::dot(w, r);
                        if (cos_r > 0) s_sky += radiance * (phong_norm * std::pow(cos_r, alpha) * weight);
                    }
                }
            }
        }
    }

    // Sun: its disc above the raymarched horizon in its own azimuth.
    const light::SunDisc disc = sky.sun();
    const glm::dvec3 e_sun(disc.irradiance);
    const bool sun_up =
        (e_sun.x > 0 || e_sun.y > 0 || e_sun.z > 0) && sun.elevation_deg > -degrees(disc.angular_radius_rad);
    const glm::dvec3 sdir = unit(sun_direction(sun));
    double frac = 0;
    if (sun_up) {
        const Marcher m{grid_, metrics_, curvature_, z_top_};
        frac = m.sun_fraction(col, row, z0, geo::azimuth_cw_from_north_to_phi(sun.azimuth_deg),
                              sun.elevation_deg * kPi / 180.0, disc.angular_radius_rad);
    }
    const double cos_ns = std::max(0.0, glm::dot(n, sdir));
    const glm::dvec3 albedo(materials_.albedo_r[t], materials_.albedo_g[t], materials_.albedo_b[t]);
    glm::dvec3 radiance(0.0);
    if (!water) {
        radiance = albedo * (e_sky + frac * cos_ns * e_sun) / kPi;
        if (ks > 0) {
            const double cos_rs = glm::dot(r, sdir);
            const double sun_lobe = cos_ns > 0 && cos_rs > 0 ? phong_norm * std::pow(cos_rs, alpha) : 0.0;
            radiance += ks * (s_sky + frac * sun_lobe * e_sun);
        }
    } else {
        // Fresnel mirror over a dark body; the mirror direction hidden by the terrain or not.
        const double f = material::fresnel_dielectric(std::clamp(glm::dot(n, v), 0.0, 1.0), 1.0, kWaterIor);
        const Marcher m{grid_, metrics_, curvature_, z_top_};
        const double r_el = std::asin(std::clamp(r.z, -1.0, 1.0));
        const bool r_visible = r.z >= 1.0 - 1e-12 || r_el > m.horizon(col, row, z0, std::atan2(r.y, r.x));
        glm::dvec3 reflected = r_visible ? glm::dvec3(sky.radiance(r)) : glm::dvec3(0.0);
        const double rad = disc.angular_radius_rad;
        if (sun_up && glm::dot(r, sdir) >= std::cos(rad)) reflected += frac * glm::dvec3(disc.disc_irradiance()) / (kPi * rad * rad);
        radiance = f * reflected + (1 - f) * double(kWaterAlbedo) * (e_sky + frac * cos_ns * e_sun) / kPi;
    }
    res.radiance = glm::vec3(radiance);
    res.sky_irradiance = glm::vec3(e_sky);
    res.sun_fraction = float(frac);
    return res;
}

std::vector<float> reference_sun_visibility(const terrain::HeightGrid& grid, double sun_azimuth_deg,
                                            double sun_elevation_deg, double sun_radius_rad, bool curvature,
                                            int threads) {
    const std::size_t n = std::size_t(checked(grid).width) * std::size_t(grid.height);
    std::vector<float> out(n, kNaNf);
    const visibility::RowMetrics metrics(grid);
    const Marcher m{grid, metrics, visibility::curvature_factor(curvature), visibility::highest_height(grid)};
    const double phi = geo::azimuth_cw_from_north_to_phi(sun_azimuth_deg);
    const double el = sun_elevation_deg * kPi / 180.0;
    parallel_for(grid.height, thread_count(threads), [&](int row, int) {
        for (int col = 0; col < grid.width; ++col) {
            const float z0 = grid.at(col, row);
            if (!std::isnan(z0)) out[grid.index(col, row)] = m.sun_fraction(col, row, z0, phi, el, sun_radius_rad);
        }
    });
    return out;
}

}  // namespace ts::render
